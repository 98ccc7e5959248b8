using System.Diagnostics;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// Runs the afl-fuzz instances of one campaign: starts them on one sync folder, shows progress, stops them on time,
/// at the first crash (<see cref="FuzzSettings.UntilCrash"/>) or when <paramref name="stop"/> fires, and waits until
/// every instance has written its stats.
/// </summary>
/// <param name="s">The settings.</param>
/// <param name="stop">Cancelled by Ctrl-C / SIGTERM.</param>
internal sealed class CampaignRunner(FuzzSettings s, CancellationToken stop)
{
    private static readonly TimeSpan Poll = TimeSpan.FromMilliseconds(500);

    // How long past the deadline an interrupted afl-fuzz may take to stop before it is killed (the loop below would
    // otherwise wait for it for ever).
    private static readonly TimeSpan Unresponsive = TimeSpan.FromSeconds(30);

    /// <summary>Runs the campaign.</summary>
    /// <param name="seeds">The -i folder.</param>
    /// <param name="dictionary">The -x file, or null.</param>
    /// <param name="view">The progress display.</param>
    /// <returns>The final stats of each instance, the wall time, and the wall time to the first crash seen (null: none).</returns>
    public (IReadOnlyList<InstanceStats> Stats, TimeSpan Wall, TimeSpan? FirstCrashWall, string Stopped) Run(string seeds, string? dictionary, ProgressView view)
    {
        int crashesBefore = CountCrashes();
        var clock = Stopwatch.StartNew();
        var instances = new List<AflInstance>();
        try
        {
            for (int i = 0; i < s.Jobs; i++)
            {
                instances.Add(AflInstance.Start(s, i, seeds, dictionary));
            }

            // afl-fuzz stops itself after -V seconds of fuzzing; start-up (.NET, dry run) comes on top, hence the grace.
            var deadline = TimeSpan.FromSeconds(s.Seconds + 120);
            TimeSpan? firstCrash = null;
            string stopped = "time";
            using var registration = stop.Register(() => instances.ForEach(x => x.Interrupt()));
            view.Run(
                () => instances.Select(x => x.Stats()).ToList(),
                () =>
                {
                    if (firstCrash is null && CountCrashes() > crashesBefore)
                    {
                        firstCrash = clock.Elapsed;
                        if (s.UntilCrash)
                        {
                            stopped = "first crash";
                            instances.ForEach(x => x.Interrupt());
                        }
                    }

                    if (stop.IsCancellationRequested)
                    {
                        stopped = "interrupted";
                    }
                    else if (clock.Elapsed > deadline + Unresponsive)
                    {
                        stopped = "deadline (afl-fuzz killed: it did not stop when interrupted)";
                        instances.ForEach(x => x.WaitOrKill(TimeSpan.Zero));
                    }
                    else if (clock.Elapsed > deadline)
                    {
                        stopped = "deadline";
                        instances.ForEach(x => x.Interrupt());
                    }

                    return instances.All(x => x.HasExited);
                },
                Poll);

            foreach (var x in instances)
            {
                x.WaitOrKill(TimeSpan.FromSeconds(30));
            }

            return (instances.Select(x => x.Stats()).ToList(), clock.Elapsed, firstCrash, stopped);
        }
        finally
        {
            foreach (var x in instances)
            {
                if (!x.HasExited)
                {
                    x.Interrupt();
                    x.WaitOrKill(TimeSpan.FromSeconds(10));
                }

                x.Dispose();
            }
        }
    }

    private int CountCrashes() =>
        Directory.Exists(s.SyncDir) ? Directory.EnumerateDirectories(s.SyncDir).Sum(d => InstanceStats.CrashFiles(d).Count()) : 0;
}
