using System.Diagnostics;

namespace AcPhys.Fuzz;

/// <summary>Times a test alone, to separate the target's own cost from the forkserver round trip in exec/s.</summary>
internal static class Bench
{
    /// <summary>Length of the pseudo-random inputs when no input folder is given.</summary>
    private const int RandomLength = 17;

    /// <summary>
    /// Runs the test on <paramref name="count"/> inputs after a warm-up: pseudo-random 17-byte inputs (fixed seed), or
    /// the files of <paramref name="inputs"/> round robin (a seed corpus or an afl queue: the inputs afl-fuzz runs,
    /// which are longer than 17 bytes and cost more).
    /// </summary>
    /// <param name="test">The test.</param>
    /// <param name="count">How many inputs to time.</param>
    /// <param name="inputs">Inputs to cycle through, or null for random ones.</param>
    /// <returns>The mean time per input and how many inputs threw.</returns>
    public static (TimeSpan PerInput, int Crashes) Run(Action<ReadOnlySpan<byte>> test, int count, IReadOnlyList<byte[]>? inputs = null)
    {
        var random = new Random(17);
        var buffer = new byte[RandomLength];
        byte[] Next(int i)
        {
            if (inputs is { Count: > 0 })
            {
                return inputs[i % inputs.Count];
            }

            random.NextBytes(buffer);
            return buffer;
        }

        int crashes = 0;
        for (int i = 0; i < 10_000; i++)
        {
            crashes += Once(test, Next(i));
        }

        crashes = 0;
        var clock = Stopwatch.StartNew();
        for (int i = 0; i < count; i++)
        {
            crashes += Once(test, Next(i));
        }

        return (clock.Elapsed / Math.Max(count, 1), crashes);
    }

    /// <summary>Reads every file of a folder (sorted by name, afl's MAX_FILE at most), the inputs of <see cref="Run"/>.</summary>
    /// <param name="dir">The folder.</param>
    /// <returns>The inputs.</returns>
    public static IReadOnlyList<byte[]> Inputs(string dir) =>
        [.. Directory.EnumerateFiles(dir).Order(StringComparer.Ordinal).Select(Replay.Read)];

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
