using System.Diagnostics;

namespace AcPhys.Cli;

/// <summary>
/// Progress for a log (stderr redirected, CI): one line on stderr every <see cref="Interval"/> while a long command
/// runs (issue 19: <c>bite</c> once printed nothing for 12 minutes into a log), e.g.
/// <c>acphys verify reference: 12/42 done after 2 min 30 s (last: LCOORD-BLOCK passed)</c>. A terminal gets the
/// Spectre display instead (<see cref="ProgressBars"/>).
/// </summary>
internal sealed class ProgressLog : IDisposable
{
    /// <summary>The environment variable that sets the interval in seconds (default 30; tests use about 1).</summary>
    public const string Variable = AcPhys.Spec.Running.ToolEnvironment.ProgressSecondsVariable;

    private readonly string title;
    private readonly int total;
    private readonly Stopwatch clock = Stopwatch.StartNew();
    private readonly Timer timer;
    private int done;
    private string? last;

    /// <summary>Initializes a new instance and starts the clock.</summary>
    /// <param name="title">What is running, e.g. <c>verify reference</c>.</param>
    /// <param name="total">The number of steps.</param>
    public ProgressLog(string title, int total)
    {
        this.title = title;
        this.total = total;
        timer = new Timer(_ => Tick(), null, Interval, Interval);
    }

    /// <summary>Gets the interval between two lines.</summary>
    public static TimeSpan Interval => AcPhys.Spec.Running.ToolEnvironment.Process.ProgressInterval;

    /// <summary>Counts one finished step.</summary>
    /// <param name="what">What just finished.</param>
    public void Advance(string what)
    {
        Volatile.Write(ref last, what);
        Interlocked.Increment(ref done);
    }

    /// <inheritdoc/>
    public void Dispose() => timer.Dispose();

    private void Tick()
    {
        string? finished = Volatile.Read(ref last);
        Console.Error.WriteLine($"acphys {title}: {Volatile.Read(ref done)}/{total} done after {Fmt.Seconds(clock.Elapsed)}{(finished is null ? string.Empty : $" (last: {finished})")}");
    }
}
