using System.Diagnostics;

namespace AcPhys.Fuzz;

/// <summary>Times a test alone, to separate the target's own cost from the forkserver round trip in exec/s.</summary>
internal static class Bench
{
    /// <summary>Runs the test on <paramref name="count"/> pseudo-random 17-byte inputs (fixed seed) after a warm-up.</summary>
    /// <param name="test">The test.</param>
    /// <param name="count">How many inputs to time.</param>
    /// <returns>The mean time per input and how many inputs threw.</returns>
    public static (TimeSpan PerInput, int Crashes) Run(Action<ReadOnlySpan<byte>> test, int count)
    {
        var random = new Random(17);
        var input = new byte[17];
        int crashes = 0;
        for (int i = 0; i < 10_000; i++)
        {
            random.NextBytes(input);
            crashes += Once(test, input);
        }

        crashes = 0;
        var clock = Stopwatch.StartNew();
        for (int i = 0; i < count; i++)
        {
            random.NextBytes(input);
            crashes += Once(test, input);
        }

        return (clock.Elapsed / Math.Max(count, 1), crashes);
    }

    private static int Once(Action<ReadOnlySpan<byte>> test, byte[] input)
    {
        try
        {
            test(input);
            return 0;
        }
#pragma warning disable CA1031 // Counting, not handling: any exception is a crash here.
        catch (Exception)
#pragma warning restore CA1031
        {
            return 1;
        }
    }
}
