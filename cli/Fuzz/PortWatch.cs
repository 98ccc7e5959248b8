using System.Diagnostics;
using System.Runtime.ExceptionServices;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// Bounds what acphys runs on an in-process port (<c>--impl</c>) outside afl-fuzz: seeds, triage, minimising (issue
/// 40). The work runs on a background thread; every new adapter instance (one per case: each check takes a fresh one)
/// is a beat, and a case not done within <see cref="Limit"/> is a hang (<see cref="PortHangException"/>). A thread that
/// never returns cannot be stopped in .NET, so the campaign then reports HANG, confirms it in a child it can kill
/// (<see cref="HangTriage"/>) and ends: the stuck thread ends with the process.
/// </summary>
/// <param name="limit">The most one case may take; <see cref="Timeout.InfiniteTimeSpan"/> runs the work inline, unwatched.</param>
internal sealed class PortWatch(TimeSpan limit)
{
    private long beats;

    /// <summary>Gets a watch that runs the work inline: the reference, a planted fault, or a child with its own answer timeout.</summary>
    public static PortWatch None { get; } = new(Timeout.InfiniteTimeSpan);

    /// <summary>Gets the most one case may take.</summary>
    public TimeSpan Limit => limit;

    /// <summary>Counts a new case (an adapter instance opened for it).</summary>
    public void Beat() => Interlocked.Increment(ref beats);

    /// <summary>Runs <paramref name="work"/>, bounded: a case that does not finish within the limit is a hang.</summary>
    /// <typeparam name="T">The work's result.</typeparam>
    /// <param name="input">How a hang names the input (the seed or file).</param>
    /// <param name="data">The input's bytes, replayed in a child to confirm a hang; null when the hanging case is not one input (a shrink candidate).</param>
    /// <param name="work">The work.</param>
    /// <returns>The work's result.</returns>
    /// <exception cref="PortHangException">A case did not finish within the limit.</exception>
    public T Run<T>(string input, byte[]? data, Func<T> work)
    {
        if (limit == Timeout.InfiniteTimeSpan)
        {
            return work();
        }

        T result = default!;
        ExceptionDispatchInfo? error = null;
        var worker = new Thread(() =>
        {
            try
            {
                result = work();
            }
#pragma warning disable CA1031 // Rethrown on the caller's thread as it was.
            catch (Exception e)
#pragma warning restore CA1031
            {
                error = ExceptionDispatchInfo.Capture(e);
            }
        })
        {
            IsBackground = true, // a hung port's thread must not keep acphys alive
            Name = "acphys fuzz --impl case",
        };

        long seen = Interlocked.Read(ref beats);
        long since = Stopwatch.GetTimestamp();
        worker.Start();
        while (!worker.Join(TimeSpan.FromMilliseconds(50)))
        {
            long now = Interlocked.Read(ref beats);
            if (now != seen)
            {
                seen = now;
                since = Stopwatch.GetTimestamp();
            }
            else if (Stopwatch.GetElapsedTime(since) > limit)
            {
                throw new PortHangException(input, data, limit);
            }
        }

        error?.Throw();
        return result;
    }
}
