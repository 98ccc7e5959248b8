using AcPhys.Studies.Numerics;
using static AcPhys.Cli.Tradeoffs.Markdown;

namespace AcPhys.Cli.Tradeoffs;

/// <summary>The accuracy tables of docs/tradeoffs.md: float32 and double mode against the exact oracle by boundary class, then indoor AABB against BSP.</summary>
internal static class AccuracyTable
{
    /// <summary>Runs the measurement and prints the tables.</summary>
    /// <param name="seed">The seed.</param>
    /// <param name="cases">Queries per source.</param>
    /// <returns>0 when the double mode never disagreed, every float32 disagreement was explained and box rooms' AABB agreed with the BSP off the tolerance bands, else 1.</returns>
    public static int Run(int seed, int cases)
    {
        Terminal.Line($"<!-- acphys tradeoffs accuracy --seed {seed} --cases {cases}; {Machine.Describe()} at start -->");
        var report = AccuracyRun.Run(seed, cases);
        Table(
            ["source", "boundary class", "queries", "float32: cells differ", "float32: pick differs", "float32: any", "why (first rounding)", "double: any"],
            report.Rows.Where(r => r.Queries > 0).Select(r => (IReadOnlyList<string>)
            [
                r.Source, r.Class, N(r.Queries), $"{N(r.Float32Cells)} ({Pct(r.Float32Cells, r.Queries)})", $"{N(r.Float32Pick)} ({Pct(r.Float32Pick, r.Queries)})",
                $"{N(r.Float32Any)} ({Pct(r.Float32Any, r.Queries)})", string.Join(", ", r.Reasons.Select(k => $"{k.Key} {N(k.Value)}")), N(r.DoubleAny),
            ]));
        var totals = report.Rows.GroupBy(r => r.Class).Select(g => (IReadOnlyList<string>)
        [
            g.Key, N(g.Sum(r => r.Queries)), $"{N(g.Sum(r => r.Float32Any))} ({Pct(g.Sum(r => r.Float32Any), g.Sum(r => r.Queries))})", N(g.Sum(r => r.DoubleAny)),
        ]);
        Table(["boundary class (all sources)", "queries", "float32 ≠ exact", "double ≠ exact"], totals);
        Terminal.Line("Examples (first per source × class × rounding):");
        Terminal.Line();
        foreach (var e in report.Examples)
        {
            Terminal.Line($"- {e.Source} / {e.Class} / {e.Reason}: `{e.Text}`");
        }

        Terminal.Line();
        Terminal.Line($"<!-- outdoor: {report.Elapsed.TotalSeconds:F1} s; {Machine.Describe()} -->");
        Terminal.Line();
        bool indoorExplained = IndoorAccuracyTable.Run(seed, Math.Max(1, cases / 50));
        Terminal.Line($"<!-- {Machine.Describe()} at end -->");
        bool clean = report.Rows.All(r => r.DoubleAny == 0 && !r.Reasons.ContainsKey("unexplained")) && indoorExplained;
        return clean ? ExitCodes.Ok : ExitCodes.Violated;
    }
}
