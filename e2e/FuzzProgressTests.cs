using AcPhys.Cli.Fuzz;

namespace AcPhys.E2E;

/// <summary>
/// The live fuzz progress line (issue #19: it froze at "execs 3,417 exec/s 1708500" while the summary said 8,374):
/// afl-fuzz 4.04c writes <c>fuzzer_stats</c> once after its dry run and then only every minute, and <c>plot_data</c>
/// only when the queue or crash count changes, so the live figures must come from the freshest sample.
/// </summary>
public sealed class FuzzProgressTests : IDisposable
{
    // What afl-fuzz 4.04c left in an instance folder a few seconds into a run (read off a land campaign on this machine).
    private const string FirstStats = "start_time        : 1796243450\nlast_update       : 1796243450\nrun_time          : 0\nexecs_done        : 391\nexecs_per_sec     : 391000.00\ncorpus_count      : 55\nstability         : 100.00%\n";
    private const string PlotHeader = "# relative_time, cycles_done, cur_item, corpus_count, pending_total, pending_favs, map_size, saved_crashes, saved_hangs, max_depth, execs_per_sec, total_execs, edges_found\n";

    private readonly string dir = Path.Combine(Path.GetTempPath(), "acphys-progress-" + Guid.NewGuid().ToString("N"), "main");

    public FuzzProgressTests()
    {
        Directory.CreateDirectory(Path.Combine(dir, "queue"));
        Directory.CreateDirectory(Path.Combine(dir, "crashes"));
        File.WriteAllText(Path.Combine(dir, "fuzzer_stats"), FirstStats);
        File.WriteAllText(Path.Combine(dir, "plot_data"), PlotHeader);
        Touch("queue", "id:000000,time:0,execs:0,orig:seed-1");
        Touch("queue", "id:000062,src:000003,time:322,execs:6380,op:havoc,rep:16");
    }

    [Fact(DisplayName = "Fuzz progress: the first fuzzer_stats (dry run, run_time 0) gives no exec/s; the newest queue or crash file gives the live execs and rate")]
    public void LiveFiguresComeFromTheFreshestSample()
    {
        Touch("crashes", "id:000003,sig:02,src:000018,time:12000,execs:351000,op:splice,rep:8");
        Touch("queue", "id:000063,src:000003,time:4000,execs:117000,op:havoc,rep:16");

        var x = InstanceStats.Read(dir);

        Assert.Equal(351_000, x.Execs);
        Assert.Equal(351_000 / 12.0, x.ExecsPerSec, 6);
        Assert.Equal(12000, x.FirstCrashMs);
        string line = ProgressView.Line(TimeSpan.FromSeconds(14), x);
        Assert.Contains("execs     351,000", line, StringComparison.Ordinal);
        Assert.Contains("exec/s    29250", line, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "Fuzz progress: under one second of fuzzing there is no rate yet, never execs divided by a millisecond")]
    public void NoRateBeforeOneSecond()
    {
        var x = InstanceStats.Read(dir);

        Assert.Equal(6380, x.Execs);
        Assert.Equal(0, x.ExecsPerSec);
    }

    [Fact(DisplayName = "Fuzz progress: once fuzzer_stats is the freshest and covers a second or more, its execs_per_sec is the figure (the summary's)")]
    public void FinalStatsWin()
    {
        File.WriteAllText(Path.Combine(dir, "fuzzer_stats"), FirstStats.Replace("run_time          : 0", "run_time          : 60", StringComparison.Ordinal)
            .Replace("execs_done        : 391", "execs_done        : 1762118", StringComparison.Ordinal)
            .Replace("391000.00", "29364.72", StringComparison.Ordinal));

        var x = InstanceStats.Read(dir);

        Assert.Equal(1_762_118, x.Execs);
        Assert.Equal(29364.72, x.ExecsPerSec, 6);
    }

    public void Dispose() => Directory.Delete(Path.GetDirectoryName(dir)!, recursive: true);

    private void Touch(string folder, string name) => File.WriteAllBytes(Path.Combine(dir, folder, name), [1]);
}
