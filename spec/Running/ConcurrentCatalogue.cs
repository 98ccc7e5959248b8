using System.Runtime.ExceptionServices;
using AcPhys.Contract;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Running;

/// <summary>
/// Runs a catalogue's invariants on several threads (issue 51) with what the one-thread run reports: the results in
/// catalogue order, progress called in catalogue order (each result once every one before it is in), and on an error
/// the error of the first invariant in catalogue order that raised one, no progress past it and no invariant after it
/// started once it is known.
/// </summary>
internal static class ConcurrentCatalogue
{
    /// <summary>Runs the invariants.</summary>
    /// <param name="invariants">The invariants, in catalogue order.</param>
    /// <param name="impl">The implementation the caller's thread asks.</param>
    /// <param name="workers">The thread count and the implementation of each extra thread.</param>
    /// <param name="run">Runs one invariant against one implementation.</param>
    /// <param name="progress">Called with each result, in catalogue order, on whichever thread completes the prefix.</param>
    /// <returns>One result per invariant, in catalogue order.</returns>
    public static IReadOnlyList<InvariantResult> Run(
        IReadOnlyList<Invariant> invariants,
        ICellPhysics impl,
        CatalogueWorkers workers,
        Func<Invariant, ICellPhysics, InvariantResult> run,
        Action<InvariantResult>? progress)
    {
        int n = invariants.Count;
        var results = new InvariantResult?[n];
        var failed = new ExceptionDispatchInfo?[n]; // the invariant's own error
        var reportFailed = new ExceptionDispatchInfo?[n]; // progress raised after the invariant's result
        int next = -1, reported = 0, stopAt = n;
        var gate = new Lock();

        void Stop(int at)
        {
            int seen;
            while (at < (seen = Volatile.Read(ref stopAt)) && Interlocked.CompareExchange(ref stopAt, at, seen) != seen)
            {
            }
        }

        void Report()
        {
            lock (gate)
            {
                while (reported < n && reported < Volatile.Read(ref stopAt) && results[reported] is { } r)
                {
                    int at = reported++;
                    try
                    {
                        progress?.Invoke(r);
                    }
                    catch (Exception e)
                    {
                        reportFailed[at] = ExceptionDispatchInfo.Capture(e);
                        Stop(at + 1);
                    }
                }
            }
        }

        void Work(ICellPhysics mine)
        {
            // Indices are taken in increasing order: once one is at or past the first error, every later one is.
            for (int i = Interlocked.Increment(ref next); i < Volatile.Read(ref stopAt); i = Interlocked.Increment(ref next))
            {
                try
                {
                    results[i] = run(invariants[i], mine);
                }
                catch (Exception e)
                {
                    failed[i] = ExceptionDispatchInfo.Capture(e);
                    Stop(i);
                }

                Report();
            }
        }

        var extra = Enumerable.Range(1, Math.Max(0, Math.Min(workers.Count, n) - 1))
            .Select(k =>
            {
                var mine = workers.Instance?.Invoke() ?? impl; // made here: a factory's error is the caller's
                return new Thread(() => Work(mine)) { IsBackground = true, Name = $"catalogue worker {k}" };
            })
            .ToList();
        foreach (var thread in extra)
        {
            thread.Start();
        }

        Work(impl);
        foreach (var thread in extra)
        {
            thread.Join();
        }

        for (int i = 0; i < n; i++)
        {
            failed[i]?.Throw();
            reportFailed[i]?.Throw();
        }

        return [.. results.Select(r => r!)];
    }
}
