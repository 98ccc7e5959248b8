using System.Globalization;
using System.Text.RegularExpressions;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// What one afl-fuzz instance has done, read from its folder: <c>fuzzer_stats</c> (written after the dry run, then
/// every minute and at exit), the last line of <c>plot_data</c> (only when the queue or the crash count changed), and
/// the names of the queue, crash and hang files (<c>time:MS,execs:N</c>, written the moment each is found).
/// </summary>
/// <remarks><para>
/// While afl-fuzz runs, the freshest of these samples gives the executions and the rate (executions over the fuzzing
/// time of that sample). <c>fuzzer_stats</c>'s own <c>execs_per_sec</c> is taken only once it covers at least a
/// second: its first write, just after the dry run, divides a few hundred executions by a millisecond or so (issue
/// #19: a live line frozen at "execs 3,417 exec/s 1708500").
/// </para></remarks>
/// <param name="Name">main, sec1, …</param>
/// <param name="Execs">Executions done.</param>
/// <param name="ExecsPerSec">Current exec/s.</param>
/// <param name="Paths">Queue entries (corpus_count).</param>
/// <param name="Crashes">Crash files saved (this run and, after a resume, earlier runs').</param>
/// <param name="Hangs">Hang files saved.</param>
/// <param name="Stability">Stability, as afl-fuzz prints it, or empty.</param>
/// <param name="FirstCrashMs">Milliseconds from the instance's start of fuzzing to its first crash this run (afl's <c>time:</c>), or null.</param>
/// <param name="FirstCrashExecs">Executions at that crash, or null.</param>
internal sealed partial record InstanceStats(string Name, long Execs, double ExecsPerSec, int Paths, int Crashes, int Hangs, string Stability, long? FirstCrashMs, long? FirstCrashExecs)
{
    /// <summary>Reads an instance's folder.</summary>
    /// <param name="dir">The instance folder inside the sync folder.</param>
    /// <returns>The stats (zeros before afl-fuzz wrote anything).</returns>
    public static InstanceStats Read(string dir)
    {
        string name = Path.GetFileName(dir);
        var stats = KeyValues(Path.Combine(dir, "fuzzer_stats"));
        var plot = LastPlotLine(Path.Combine(dir, "plot_data"));
        var crashFiles = CrashFiles(dir).ToList();
        var current = CrashFiles(dir, currentOnly: true).Select(Sample).OfType<(long Ms, long Execs)>().OrderBy(t => t.Ms).ToList();
        var hangFiles = Directory.Exists(Path.Combine(dir, "hangs")) ? Directory.EnumerateFiles(Path.Combine(dir, "hangs"), "id:*").ToList() : [];
        var queueFiles = Directory.Exists(Path.Combine(dir, "queue")) ? Directory.EnumerateFiles(Path.Combine(dir, "queue"), "id:*") : [];
        var fromStats = (Ms: Long(stats, "run_time") * 1000, Execs: Long(stats, "execs_done"));
        var fromPlot = (Ms: Long(plot, "relative_time") * 1000, Execs: Long(plot, "total_execs"));
        var freshest = queueFiles.Concat(crashFiles).Concat(hangFiles).Select(Sample).OfType<(long Ms, long Execs)>()
            .Append(fromStats).Append(fromPlot).MaxBy(t => (t.Execs, t.Ms));
        double rate = fromStats.Execs >= freshest.Execs && fromStats.Ms >= 1000 && Double(stats, "execs_per_sec") > 0
            ? Double(stats, "execs_per_sec")
            : Rate(freshest.Execs, freshest.Ms);
        int paths = (int)Math.Max(Long(stats, "corpus_count"), Long(plot, "corpus_count"));
        int hangs = hangFiles.Count;
        return new InstanceStats(
            name,
            freshest.Execs,
            rate,
            paths,
            crashFiles.Count,
            hangs,
            stats.GetValueOrDefault("stability", string.Empty),
            current.Count > 0 ? current[0].Ms : null,
            current.Count > 0 ? current[0].Execs : null);
    }

    /// <summary>Lists an instance's crash files: <c>crashes/</c> and the <c>crashes.DATE/</c> folders afl-fuzz keeps on resume.</summary>
    /// <param name="dir">The instance folder.</param>
    /// <param name="currentOnly">Only this run's <c>crashes/</c>.</param>
    /// <returns>The files.</returns>
    public static IEnumerable<string> CrashFiles(string dir, bool currentOnly = false) =>
        !Directory.Exists(dir)
            ? []
            : Directory.EnumerateDirectories(dir, currentOnly ? "crashes" : "crashes*")
                .SelectMany(d => Directory.EnumerateFiles(d, "id:*"))
                .Order(StringComparer.Ordinal);

    /// <summary>Lists an instance's hang files: <c>hangs/</c> and the <c>hangs.DATE/</c> folders afl-fuzz keeps on resume.</summary>
    /// <param name="dir">The instance folder.</param>
    /// <returns>The files.</returns>
    public static IEnumerable<string> HangFiles(string dir) =>
        !Directory.Exists(dir)
            ? []
            : Directory.EnumerateDirectories(dir, "hangs*").SelectMany(d => Directory.EnumerateFiles(d, "id:*")).Order(StringComparer.Ordinal);

    /// <summary>Gives the executions per second of <paramref name="execs"/> over <paramref name="ms"/> of fuzzing, or 0 under a second (no honest rate yet).</summary>
    /// <param name="execs">Executions.</param>
    /// <param name="ms">Milliseconds of fuzzing.</param>
    /// <returns>The rate.</returns>
    public static double Rate(long execs, long ms) => ms >= 1000 ? execs * 1000.0 / ms : 0;

    // "id:000063,src:000003,time:498,execs:9828,op:havoc,rep:16": afl time (ms) and executions when the file was saved.
    private static (long Ms, long Execs)? Sample(string file) =>
        TimeExecs().Match(Path.GetFileName(file)) is { Success: true } m
            ? (long.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture), long.Parse(m.Groups[2].Value, CultureInfo.InvariantCulture))
            : null;

    private static Dictionary<string, string> KeyValues(string file)
    {
        var d = new Dictionary<string, string>(StringComparer.Ordinal);
        if (!File.Exists(file))
        {
            return d;
        }

        foreach (string line in ReadShared(file).Split('\n'))
        {
            int colon = line.IndexOf(':', StringComparison.Ordinal);
            if (colon > 0)
            {
                d[line[..colon].Trim()] = line[(colon + 1)..].Trim();
            }
        }

        return d;
    }

    // plot_data: "# relative_time, cycles_done, cur_item, corpus_count, …, execs_per_sec, total_execs, edges_found".
    private static Dictionary<string, string> LastPlotLine(string file)
    {
        var d = new Dictionary<string, string>(StringComparer.Ordinal);
        if (!File.Exists(file))
        {
            return d;
        }

        var lines = ReadShared(file).Split('\n', StringSplitOptions.RemoveEmptyEntries);
        if (lines.Length < 2 || !lines[0].StartsWith('#'))
        {
            return d;
        }

        var header = lines[0].TrimStart('#').Split(',', StringSplitOptions.TrimEntries);
        var values = lines[^1].Split(',', StringSplitOptions.TrimEntries);
        for (int i = 0; i < Math.Min(header.Length, values.Length); i++)
        {
            d[header[i]] = values[i].TrimEnd('%');
        }

        return d;
    }

    private static string ReadShared(string file)
    {
        try
        {
            using var stream = new FileStream(file, FileMode.Open, FileAccess.Read, FileShare.ReadWrite | FileShare.Delete);
            using var reader = new StreamReader(stream);
            return reader.ReadToEnd();
        }
        catch (IOException)
        {
            return string.Empty;
        }
    }

    private static long Long(Dictionary<string, string> d, string key) =>
        d.TryGetValue(key, out var v) && long.TryParse(v, NumberStyles.Integer, CultureInfo.InvariantCulture, out long n) ? n : 0;

    private static double Double(Dictionary<string, string> d, string key) =>
        d.TryGetValue(key, out var v) && double.TryParse(v, NumberStyles.Float, CultureInfo.InvariantCulture, out double n) ? n : 0;

    [GeneratedRegex(@",time:(\d+),execs:(\d+)")]
    private static partial Regex TimeExecs();
}
