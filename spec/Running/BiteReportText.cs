using System.Globalization;
using System.Text;
using System.Text.Json;

namespace AcPhys.Spec.Running;

/// <summary>Writes a bite run as markdown (the docs/bite.md tables) and as JSON (format <c>acphys-bite</c>, version 1).</summary>
public static class BiteReportText
{
    /// <summary>The value of the JSON <c>format</c> field.</summary>
    public const string FormatName = "acphys-bite";

    private static readonly JsonWriterOptions WriterOptions = new() { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping };

    /// <summary>Formats a time to detect in milliseconds (two decimals below 10 ms, else one), or "—".</summary>
    /// <param name="t">The time.</param>
    /// <returns>The text.</returns>
    public static string Ms(TimeSpan? t) => t is { } v
        ? v.TotalMilliseconds.ToString(v.TotalMilliseconds < 10 ? "0.00" : "0.0", CultureInfo.InvariantCulture) + " ms"
        : "—";

    /// <summary>Returns the matrix mark of a cell: ● caught under every seed, k/N under some, · not caught, – not applicable.</summary>
    /// <param name="cell">The cell.</param>
    /// <param name="seeds">Seeds in the run.</param>
    /// <returns>The mark.</returns>
    public static string Mark(BiteCell cell, int seeds) => cell.Verdict switch
    {
        BiteVerdict.Caught => "●",
        BiteVerdict.Sometimes => $"{cell.SeedsCaught}/{seeds}",
        BiteVerdict.NotCaught => "·",
        _ => "–",
    };

    /// <summary>Returns the one-line summary.</summary>
    /// <param name="report">The report.</param>
    /// <returns>The line.</returns>
    public static string Summary(BiteReport report)
    {
        var run = report.Run.ToList();
        int caught = run.Count(b => b.Status == BugStatus.Caught);
        string pct = run.Count == 0 ? "—" : (100.0 * caught / run.Count).ToString("0.#", CultureInfo.InvariantCulture) + " %";
        var medians = run.Select(b => b.Median).OfType<TimeSpan>().ToList();
        var maxes = run.Select(b => b.Max).OfType<TimeSpan>().ToList();
        int pending = report.Pending.Count();
        return $"{caught} of {run.Count} catalogue bugs caught ({pct}) under {report.Seeds} seed(s) of the {report.Profile.Name} profile"
            + $"; median time to detect {Ms(BiteStats.Median(medians))} (median over bugs; slowest bug median {Ms(medians.Count == 0 ? null : medians.Max())}, max {Ms(maxes.Count == 0 ? null : maxes.Max())})"
            + (pending > 0 ? $"; {pending} pending (fault not available yet)" : string.Empty);
    }

    /// <summary>Writes the markdown report.</summary>
    /// <param name="report">The report.</param>
    /// <param name="command">The command line that produced it (shown in the header).</param>
    /// <returns>The text.</returns>
    public static string Markdown(BiteReport report, string command)
    {
        var s = new StringBuilder();
        s.AppendLine("# Bite report").AppendLine();
        s.AppendLine(CultureInfo.InvariantCulture, $"`{command}`: profile **{report.Profile.Name}** ({report.Profile.CasesPerInvariant:N0} generated cases per invariant, no exhaustive sweeps), {report.Seeds} seed(s) from base seed {report.BaseSeed}, {report.InvariantIds.Count} invariants, run time {report.Elapsed.TotalSeconds:0.0} s.").AppendLine();
        s.AppendLine(Summary(report) + ".").AppendLine();
        s.AppendLine("Time to detect: per seed, the soonest any invariant reached a violating case (before shrinking); median and max over the seeds.").AppendLine();
        s.AppendLine("| Bug | Fault | Status | Caught by (every seed) | Median | Max | Cases (seed 0) |");
        s.AppendLine("|---|---|---|---|---:|---:|---:|");
        foreach (var b in report.Bugs)
        {
            string status = b.Status switch
            {
                BugStatus.Caught => "caught",
                BugStatus.Escaped => "**ESCAPED**",
                _ => "pending: " + b.Bug.NotAvailableReason,
            };
            string cases = b.CasesToDetect.Count > 0 && b.CasesToDetect[0] is int n ? n.ToString(CultureInfo.InvariantCulture) : "—";
            s.AppendLine(CultureInfo.InvariantCulture, $"| `{b.Bug.Id}` | `{b.Bug.Fault}` | {status} | {string.Join(", ", b.CaughtBy)} | {Ms(b.Median)} | {Ms(b.Max)} | {cases} |");
        }

        s.AppendLine().AppendLine("## Matrix").AppendLine();
        s.AppendLine("● caught under every seed, k/N under k of N seeds, · not caught, – not applicable (the faulty implementation lacks an operation or declares another pick). Columns:");
        s.AppendLine(string.Join(", ", report.InvariantIds.Select((id, i) => $"{i + 1} `{id}`")) + ".").AppendLine();
        s.AppendLine("| Bug | " + string.Join(" | ", report.InvariantIds.Select((_, i) => (i + 1).ToString(CultureInfo.InvariantCulture))) + " |");
        s.AppendLine("|---|" + string.Concat(report.InvariantIds.Select(_ => ":-:|")));
        foreach (var b in report.Run)
        {
            var byId = b.Cells.ToDictionary(c => c.InvariantId);
            s.AppendLine($"| `{b.Bug.Id}` | " + string.Join(" | ", report.InvariantIds.Select(id => byId.TryGetValue(id, out var c) ? Mark(c, report.Seeds) : " ")) + " |");
        }

        return s.ToString();
    }

    /// <summary>Writes the JSON report.</summary>
    /// <param name="report">The report.</param>
    /// <returns>The text, ending in a newline.</returns>
    public static string Json(BiteReport report)
    {
        using var buffer = new MemoryStream();
        using (var w = new Utf8JsonWriter(buffer, WriterOptions))
        {
            w.WriteStartObject();
            w.WriteString("format", FormatName);
            w.WriteNumber("version", 1);
            w.WriteString("profile", report.Profile.Name);
            w.WriteNumber("casesPerInvariant", report.Profile.CasesPerInvariant);
            w.WriteString("baseSeed", report.BaseSeed.ToString(CultureInfo.InvariantCulture));
            w.WriteNumber("seeds", report.Seeds);
            w.WriteNumber("elapsedMs", Math.Round(report.Elapsed.TotalMilliseconds, 1));
            Strings(w, "invariants", report.InvariantIds);
            w.WriteStartObject("summary");
            w.WriteNumber("run", report.Run.Count());
            w.WriteNumber("caught", report.Bugs.Count(b => b.Status == BugStatus.Caught));
            w.WriteNumber("escaped", report.Escaped.Count());
            w.WriteNumber("pending", report.Pending.Count());
            w.WriteEndObject();
            w.WriteStartArray("bugs");
            foreach (var b in report.Bugs)
            {
                Bug(w, b);
            }

            w.WriteEndArray();
            w.WriteEndObject();
        }

        return Encoding.UTF8.GetString(buffer.ToArray()) + "\n";
    }

    private static void Bug(Utf8JsonWriter w, BugBite b)
    {
        w.WriteStartObject();
        w.WriteString("id", b.Bug.Id);
        w.WriteString("fault", b.Bug.Fault);
        w.WriteString("status", b.Status.ToString().ToLowerInvariant());
        if (b.Bug.NotAvailableReason is { } reason)
        {
            w.WriteString("reason", reason);
        }

        Strings(w, "declared", b.Bug.CaughtBy);
        Strings(w, "caughtBy", [.. b.CaughtBy]);
        Strings(w, "missedDeclared", [.. b.MissedDeclared]);
        w.WriteStartArray("timeToDetectMs");
        foreach (var t in b.TimeToDetect)
        {
            if (t is { } v)
            {
                w.WriteNumberValue(Math.Round(v.TotalMilliseconds, 3));
            }
            else
            {
                w.WriteNullValue();
            }
        }

        w.WriteEndArray();
        w.WriteStartArray("casesToDetect");
        foreach (var n in b.CasesToDetect)
        {
            if (n is int v)
            {
                w.WriteNumberValue(v);
            }
            else
            {
                w.WriteNullValue();
            }
        }

        w.WriteEndArray();
        if (b.Median is { } median)
        {
            w.WriteNumber("medianMs", Math.Round(median.TotalMilliseconds, 3));
            w.WriteNumber("maxMs", Math.Round(b.Max!.Value.TotalMilliseconds, 3));
        }

        w.WriteStartObject("cells");
        foreach (var c in b.Cells)
        {
            w.WriteStartObject(c.InvariantId);
            w.WriteString("verdict", c.Verdict switch
            {
                BiteVerdict.Caught => "caught",
                BiteVerdict.Sometimes => "sometimes",
                BiteVerdict.NotCaught => "not-caught",
                _ => "not-applicable",
            });
            w.WriteNumber("seedsCaught", c.SeedsCaught);
            w.WriteEndObject();
        }

        w.WriteEndObject();
        if (b.Example is { } e)
        {
            w.WriteStartObject("example");
            w.WriteString("invariant", e.InvariantId);
            w.WriteString("message", e.Violation.Message);
            w.WriteString("case", e.Violation.CaseText);
            w.WriteString("replaySeed", e.Replay.ToString());
            w.WriteEndObject();
        }

        w.WriteEndObject();
    }

    private static void Strings(Utf8JsonWriter w, string name, IReadOnlyList<string> values)
    {
        w.WriteStartArray(name);
        foreach (var v in values)
        {
            w.WriteStringValue(v);
        }

        w.WriteEndArray();
    }
}
