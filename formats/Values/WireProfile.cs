using System.Collections.Concurrent;
using System.Diagnostics;
using System.Globalization;

namespace AcPhys.Formats.Values;

/// <summary>
/// An opt-in stopwatch breakdown of the served path (issue 26; docs/protocol.md, "Speed"): with
/// <c>ACPHYS_WIRE_PROFILE=1</c> in the environment, the tool and <c>acphys serve</c> (which inherits it) each print on
/// stderr at exit how long they spent in each stage and how often. Off, a stage costs one branch. The tool switches it
/// on at start (<see cref="WireProfileSwitch.Enable"/>, from spec's <c>ToolEnvironment</c>): formats reads no environment.
/// </summary>
/// <remarks>Stages may nest (a request line's build includes its scene's records); the table says which.</remarks>
internal static class WireProfile
{
    private static readonly ConcurrentDictionary<string, long[]> Totals = new(StringComparer.Ordinal);

    private static int enabled;

    /// <summary>Gets a value indicating whether the breakdown is collected.</summary>
    public static bool On { get; private set; }

    /// <summary>Switches the breakdown on for the rest of the process; it is printed at exit.</summary>
    public static void Enable()
    {
        if (Interlocked.Exchange(ref enabled, 1) == 0)
        {
            On = true;
            AppDomain.CurrentDomain.ProcessExit += (_, _) => Print();
        }
    }

    /// <summary>Starts timing a stage.</summary>
    /// <returns>The start, or 0 when off.</returns>
    public static long Start() => On ? Stopwatch.GetTimestamp() : 0;

    /// <summary>Adds the time since <paramref name="started"/> to a stage.</summary>
    /// <param name="stage">The stage's name.</param>
    /// <param name="started">What <see cref="Start"/> returned.</param>
    public static void Stop(string stage, long started)
    {
        if (!On)
        {
            return;
        }

        var t = Totals.GetOrAdd(stage, _ => new long[2]);
        Interlocked.Add(ref t[0], Stopwatch.GetTimestamp() - started);
        Interlocked.Increment(ref t[1]);
    }

    /// <summary>Times a stage around a call.</summary>
    /// <typeparam name="T">The result.</typeparam>
    /// <param name="stage">The stage's name.</param>
    /// <param name="f">The call.</param>
    /// <returns>Its result.</returns>
    public static T Time<T>(string stage, Func<T> f)
    {
        if (!On)
        {
            return f();
        }

        long s = Start();
        try
        {
            return f();
        }
        finally
        {
            Stop(stage, s);
        }
    }

    private static void Print()
    {
        var lines = Totals.OrderBy(e => e.Key, StringComparer.Ordinal).Select(e => string.Create(
            CultureInfo.InvariantCulture,
            $"  {e.Key,-48} {Stopwatch.GetElapsedTime(0, e.Value[0]).TotalMilliseconds,10:0.0} ms {e.Value[1],9} x {Stopwatch.GetElapsedTime(0, e.Value[0]).TotalMilliseconds * 1000 / Math.Max(1, e.Value[1]),9:0.0} µs"));
        string gc = string.Create(
            CultureInfo.InvariantCulture,
            $"  gc: {GC.CollectionCount(0)} gen0, {GC.CollectionCount(1)} gen1, {GC.CollectionCount(2)} gen2; paused {GC.GetTotalPauseDuration().TotalMilliseconds:0} ms; allocated {GC.GetTotalAllocatedBytes() / (1024.0 * 1024):0} MiB; JIT {System.Runtime.JitInfo.GetCompilationTime().TotalMilliseconds:0} ms ({System.Runtime.JitInfo.GetCompiledMethodCount()} methods)");
        Console.Error.WriteLine($"wire profile (pid {Environment.ProcessId}, {Process.GetCurrentProcess().TotalProcessorTime.TotalSeconds:0.0} s CPU):{Environment.NewLine}{gc}{Environment.NewLine}{string.Join(Environment.NewLine, lines)}");
    }
}
