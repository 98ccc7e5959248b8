using System.Diagnostics;
using System.Globalization;
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
    /// <summary>The variable that sets the budget in milliseconds (0: no warm-up).</summary>
    public const string BudgetVariable = "ACPHYS_FUZZ_WARMUP_MS";

    /// <summary>The default budget: about two rounds of .NET tiered compilation under load (call counting starts 100 ms after the last new method).</summary>
    public const int DefaultBudgetMs = 3000;

    /// <summary>Reads the budget from <see cref="BudgetVariable"/>.</summary>
    /// <returns>The budget, or null when the variable is malformed (the caller reports it).</returns>
    public static TimeSpan? BudgetFromEnvironment()
    {
        string? text = Environment.GetEnvironmentVariable(BudgetVariable);
        if (text is not { Length: > 0 })
        {
            return TimeSpan.FromMilliseconds(DefaultBudgetMs);
        }

        return int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out int ms) && ms <= 60_000 ? TimeSpan.FromMilliseconds(ms) : null;
    }

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
