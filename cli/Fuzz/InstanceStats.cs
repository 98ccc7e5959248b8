using System.Globalization;
using System.Text.RegularExpressions;

namespace AcPhys.Cli.Fuzz;

/// <summary>
/// What one afl-fuzz instance has done, read from its folder: <c>fuzzer_stats</c> (written at exit and every minute),
/// else the last line of <c>plot_data</c> (every 5 s), and the crash files themselves (counted at once).
/// </summary>
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
        long execs = Math.Max(Long(stats, "execs_done"), Long(plot, "total_execs"));
        double rate = plot.Count > 0 && !stats.ContainsKey("execs_done") ? Double(plot, "execs_per_sec") : Double(stats, "execs_per_sec");
        int paths = (int)Math.Max(Long(stats, "corpus_count"), Long(plot, "corpus_count"));
        var crashFiles = CrashFiles(dir).ToList();
        var current = CrashFiles(dir, currentOnly: true).Select(f => TimeExecs().Match(Path.GetFileName(f))).Where(m => m.Success)
            .Select(m => (Ms: long.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture), Execs: long.Parse(m.Groups[2].Value, CultureInfo.InvariantCulture)))
            .OrderBy(t => t.Ms).ToList();
        int hangs = Directory.Exists(Path.Combine(dir, "hangs")) ? Directory.EnumerateFiles(Path.Combine(dir, "hangs"), "id:*").Count() : 0;
        return new InstanceStats(
            name,
            execs,
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
