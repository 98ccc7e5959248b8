using AcPhys.Fuzz.Targets;
using Xunit;

namespace AcPhys.Fuzz.Tests;

public sealed class DatRecordsTargetTests
{
    [Fact(DisplayName = "dat-records: every prefix, every single-byte change and every count blown up of every seed is read or refused with InputFormatException only.")]
    public void Mutated_seeds_never_crash_the_reader()
    {
        var test = FuzzTargets.Find("dat-records")!.CreateTest(fault: null);
        var corpus = Path.Combine(RepoPaths.Root, "corpus", "fuzz", "dat-records");
        var seeds = FuzzTargets.Find("dat-records")!.Seeds.Values.Concat(Directory.Exists(corpus) ? Directory.GetFiles(corpus).Select(File.ReadAllBytes) : []).ToList();
        Assert.NotEmpty(seeds);
        int runs = 0;
        foreach (var seed in seeds)
        {
            for (int n = 0; n <= seed.Length; n++)
            {
                test(seed.AsSpan(0, n));
                runs++;
            }

            for (int i = 1; i < seed.Length; i++)
            {
                foreach (byte b in new byte[] { 0x00, 0xFF, 0x7F, (byte)(seed[i] ^ 0x01) })
                {
                    var copy = (byte[])seed.Clone();
                    copy[i] = b;
                    test(copy);
                    runs++;
                }
            }

            test([.. seed, 0x00]); // a trailing byte
            runs++;
        }

        Assert.True(runs > 1000);
    }
}
