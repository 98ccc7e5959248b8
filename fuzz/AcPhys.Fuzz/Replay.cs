namespace AcPhys.Fuzz;

/// <summary>Runs saved inputs outside afl-fuzz, and adapts a span test to SharpFuzz's stream callback.</summary>
internal static class Replay
{
    /// <summary>afl-fuzz's MAX_FILE: longer inputs are cut, as afl-fuzz would never write them.</summary>
    private const int MaxInput = 1 << 20;

    /// <summary>Replays one saved input (a crash from findings/, a seed).</summary>
    /// <param name="path">The input file.</param>
    /// <param name="test">The test.</param>
    /// <param name="log">Where to report the outcome.</param>
    /// <returns>0 when the test passed, 1 when it threw (the exception is written to <paramref name="log"/>).</returns>
    public static int Run(string path, Action<ReadOnlySpan<byte>> test, TextWriter log)
    {
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

    /// <summary>Reads a saved input as afl-fuzz would hand it over (cut at afl's MAX_FILE).</summary>
    /// <param name="path">The input file.</param>
    /// <returns>The input.</returns>
    public static byte[] Read(string path)
    {
        byte[] data = File.ReadAllBytes(path);
        return data.Length <= MaxInput ? data : data[..MaxInput];
    }

    /// <summary>Wraps a span test as SharpFuzz's callback: the whole stream (one input) is read into a reused buffer.</summary>
    /// <param name="test">The test.</param>
    /// <returns>The callback; not thread-safe (SharpFuzz runs one input at a time).</returns>
    public static Action<Stream> FromStream(Action<ReadOnlySpan<byte>> test)
    {
        var buffer = new MemoryStream();
        return stream =>
        {
            buffer.SetLength(0);
            stream.CopyTo(buffer);
            int length = (int)Math.Min(buffer.Length, MaxInput);
            test(buffer.GetBuffer().AsSpan(0, length));
        };
    }
}
