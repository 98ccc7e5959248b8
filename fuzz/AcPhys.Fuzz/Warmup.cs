using System.Diagnostics;
using AcPhys.Fuzz.Targets;

namespace AcPhys.Fuzz;

/// <summary>
/// Warms an <c>--impl-cmd</c> child before afl-fuzz's clock starts (issue 40): a fixed set of inputs (the target's
/// built-in seeds, then pseudo-random inputs of the seeds' lengths, fixed seed) runs through the test until a time
/// budget is spent, so the child's JIT has compiled its hot paths (and the harness's wire code its own) before the
/// first timed input. Without it, the first few hundred served inputs cost several times a warm one, which is where a
/// planted fault's first finding falls.
/// </summary>
internal static class Warmup
{
    /// <summary>Runs warm-up inputs until <paramref name="budget"/> is spent; findings here are not reported (afl-fuzz finds them again).</summary>
    /// <param name="test">The test (a child that fails is restarted by it, as under afl-fuzz).</param>
    /// <param name="target">The target (its seeds come first).</param>
    /// <param name="budget">The time to spend.</param>
    /// <param name="chunk">Called after every 100 inputs with their mean time (the warm-up curve), or null.</param>
    /// <returns>How many inputs ran.</returns>
    public static int Run(Action<ReadOnlySpan<byte>> test, FuzzTarget target, TimeSpan budget, Action<int, TimeSpan>? chunk = null)
    {
        var seeds = target.Seeds.Values.ToArray();
        int[] lengths = [.. seeds.Select(s => s.Length).Where(n => n > 0).DefaultIfEmpty(17)];
        var random = new Random(40);
        var clock = Stopwatch.StartNew();
        var since = clock.Elapsed;
        int n = 0;
        while (clock.Elapsed < budget)
        {
            byte[] input = n < seeds.Length ? seeds[n] : new byte[lengths[n % lengths.Length]];
            if (n >= seeds.Length)
            {
                random.NextBytes(input);
            }

            try
            {
                test(input);
            }
#pragma warning disable CA1031 // A warm-up input that fails (or crashes the child) is afl-fuzz's to find, not this loop's.
            catch (Exception)
#pragma warning restore CA1031
            {
            }

            n++;
            if (chunk is not null && n % 100 == 0)
            {
                chunk(n, (clock.Elapsed - since) / 100);
                since = clock.Elapsed;
            }
        }

        return n;
    }
}
