using System.Globalization;
using Spectre.Console;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// Live progress per afl-fuzz instance (exec/s, paths, crashes): a Spectre live table on a terminal, one line per
/// instance every 30 s in a log, nothing with <c>--quiet</c>.
/// </summary>
/// <param name="quiet">Print nothing while running.</param>
internal sealed class ProgressView(bool quiet)
{
    private static readonly TimeSpan LogEvery = TimeSpan.FromSeconds(30);

    /// <summary>Polls until <paramref name="tick"/> returns true, showing <paramref name="read"/>'s stats.</summary>
    /// <param name="read">Reads the current stats.</param>
    /// <param name="tick">Called every <paramref name="poll"/>; returns true when the campaign is over.</param>
    /// <param name="poll">The poll interval.</param>
    public void Run(Func<IReadOnlyList<InstanceStats>> read, Func<bool> tick, TimeSpan poll)
    {
        if (quiet)
        {
            while (!tick())
            {
                Thread.Sleep(poll);
            }

            return;
        }

        if (Terminal.ShowsProgress)
        {
            var table = Table();
            Terminal.Err.Live(table).Start(ctx =>
            {
                while (!tick())
                {
                    Fill(table, read());
                    ctx.Refresh();
                    Thread.Sleep(poll);
                }

                Fill(table, read());
                ctx.Refresh();
            });
            return;
        }

        var clock = System.Diagnostics.Stopwatch.StartNew();
        var last = TimeSpan.Zero;
        while (!tick())
        {
            if (clock.Elapsed - last >= LogEvery)
            {
                last = clock.Elapsed;
                foreach (var x in read())
                {
                    Console.Error.WriteLine(Line(clock.Elapsed, x));
                }
            }

            Thread.Sleep(poll);
        }
    }

    /// <summary>Formats one instance as a log line.</summary>
    /// <param name="at">Time since start.</param>
    /// <param name="x">The stats.</param>
    /// <returns>The line.</returns>
    public static string Line(TimeSpan at, InstanceStats x) => string.Create(
        CultureInfo.InvariantCulture,
        $"[fuzz {at:hh\\:mm\\:ss}] {x.Name,-5} execs {x.Execs,11:N0}  exec/s {x.ExecsPerSec,8:F0}  paths {x.Paths,6}  crashes {x.Crashes,4}  hangs {x.Hangs,3}");

    private static Table Table() => new Table().AddColumns("instance", "execs", "exec/s", "paths", "crashes", "hangs");

    private static void Fill(Table table, IReadOnlyList<InstanceStats> stats)
    {
        table.Rows.Clear();
        foreach (var x in stats)
        {
            table.AddRow(
                x.Name,
                x.Execs.ToString("N0", CultureInfo.InvariantCulture),
                x.ExecsPerSec.ToString("F0", CultureInfo.InvariantCulture),
                x.Paths.ToString(CultureInfo.InvariantCulture),
                x.Crashes > 0 ? $"[red bold]{x.Crashes}[/]" : "0",
                x.Hangs.ToString(CultureInfo.InvariantCulture));
        }
    }
}
