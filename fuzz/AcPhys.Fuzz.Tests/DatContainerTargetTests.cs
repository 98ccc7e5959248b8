using AcPhys.Fuzz.Targets;
using Xunit;

namespace AcPhys.Fuzz.Tests;

public sealed class DatContainerTargetTests
{
    [Fact(DisplayName = "dat-container: every prefix, every single-word change of every seed is read or refused with DatContainerException only.")]
    public void Mutated_seeds_never_crash_the_reader()
    {
        var target = FuzzTargets.Find("dat-container")!;
        var test = target.CreateTest(fault: null);
        int runs = 0;
        foreach (var seed in target.Seeds.Values)
        {
            for (int n = 0; n <= seed.Length; n += 3)
            {
                test(seed.AsSpan(0, n));
                runs++;
            }

            // Every u32 (links, counts, branches, offsets, sizes) set to values a hostile file holds.
            for (int i = 0; i + 4 <= seed.Length; i += 4)
            {
                foreach (uint v in new uint[] { 0, 1, 0xFFFFFFFF, 0x140, (uint)seed.Length - 2, (uint)i, 62 })
                {
                    var copy = (byte[])seed.Clone();
                    BitConverter.TryWriteBytes(copy.AsSpan(i), v);
                    test(copy);
                    runs++;
                }
            }
        }

        Assert.True(runs > 10000, $"{runs} runs");
    }
}
