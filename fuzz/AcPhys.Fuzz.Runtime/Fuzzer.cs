using System.Globalization;

namespace AcPhys.Fuzz.Runtime;

/// <summary>Entry points for a fuzzing harness (the SharpFuzz <c>Fuzzer.Run</c> / <c>RunOnce</c> stand-in).</summary>
public static class Fuzzer
{
    /// <summary>
    /// Runs <paramref name="test"/> for afl-fuzz: under afl-fuzz (<c>__AFL_SHM_ID</c> set) it serves inputs until
    /// afl-fuzz goes away; otherwise it runs the test once on the input and lets any exception escape.
    /// </summary>
    /// <param name="test">The test. An exception escaping it is reported to afl-fuzz as a crash (SIGABRT).</param>
    /// <param name="inputPath">The file afl-fuzz writes each input to (its <c>@@</c> argument), or null for stdin.</param>
    /// <returns>The exit code for <c>Main</c>.</returns>
    public static int Run(Action<ReadOnlySpan<byte>> test, string? inputPath = null)
    {
        ArgumentNullException.ThrowIfNull(test);
        var input = new InputSource(inputPath);
        string? shm = Environment.GetEnvironmentVariable(Protocol.ShmEnvVar);
        if (shm is not null && int.TryParse(shm, NumberStyles.Integer, CultureInfo.InvariantCulture, out int shmId))
        {
            return ForkServer.Serve(shmId, test, input);
        }

        test(input.Read());
        return 0;
    }

    /// <summary>Replays one saved input (a crash from findings/, a seed) outside afl-fuzz.</summary>
    /// <param name="path">The input file.</param>
    /// <param name="test">The test.</param>
    /// <param name="log">Where to report the outcome; null for standard error.</param>
    /// <returns>0 when the test passed, 1 when it threw (the exception is written to <paramref name="log"/>).</returns>
    public static int RunOnce(string path, Action<ReadOnlySpan<byte>> test, TextWriter? log = null)
    {
        ArgumentNullException.ThrowIfNull(test);
        log ??= Console.Error;
        byte[] data = File.ReadAllBytes(path);
        try
        {
            test(data);
            log.WriteLine($"ok: {path} ({data.Length} bytes)");
            return 0;
        }
#pragma warning disable CA1031 // Reporting any exception is the point of a replay.
        catch (Exception e)
#pragma warning restore CA1031
        {
            log.WriteLine($"CRASH: {path} ({data.Length} bytes)");
            log.WriteLine(e);
            return 1;
        }
    }
}
