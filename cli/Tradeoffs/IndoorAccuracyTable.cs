using AcPhys.Studies.Numerics;
using static AcPhys.Cli.Tradeoffs.Markdown;

namespace AcPhys.Cli.Tradeoffs;

/// <summary>The indoor rows of the accuracy tables (docs/tradeoffs.md §2): AABB cells against retail's BSP, by room shape and boundary class.</summary>
internal static class IndoorAccuracyTable
{
    /// <summary>Scattered bodies per generated scene and shape.</summary>
    public const int Scatter = 24;

    /// <summary>Runs the measurement and prints the tables.</summary>
    /// <param name="seed">The seed.</param>
    /// <param name="scenes">Generated scenes (each in every room shape).</param>
    /// <returns>True when box rooms agree everywhere off the tolerance bands (interior, outdoor): every disagreement is explained.</returns>
    public static bool Run(int seed, int scenes)
    {
        var report = IndoorAccuracyRun.Run(seed, scenes, Scatter);
        Terminal.Line($"**Indoor: AABB cells against retail's BSP** ({report.Scenes} generated scenes, each with box, L-shaped and stairs rooms; {Scatter} scattered bodies per scene and shape, each queried from its room and from the land cell):");
        Terminal.Line();
        Table(
            ["source", "room shape", "boundary class", "queries", "AABB: cells differ", "AABB: pick differs", "AABB ≠ BSP", "kinds"],
            report.Rows.Where(r => r.Queries > 0).Select(r => (IReadOnlyList<string>)
            [
                r.Source, r.Shape, r.Class, N(r.Queries), $"{N(r.CellsDiffer)} ({Pct(r.CellsDiffer, r.Queries)})", $"{N(r.PickDiffers)} ({Pct(r.PickDiffers, r.Queries)})",
                $"{N(r.Any)} ({Pct(r.Any, r.Queries)})", string.Join(", ", r.Reasons.Select(k => $"{k.Key} {N(k.Value)}")),
            ]));
        var shapes = report.Rows.Select(r => r.Shape).Distinct().ToList();
        Table(
            ["boundary class (both sources)", .. shapes.Select(s => $"{s}: AABB ≠ BSP")],
            report.Rows.GroupBy(r => r.Class).Select(g => (IReadOnlyList<string>)
            [
                g.Key, .. shapes.Select(s => Cell(g.Where(r => r.Shape == s).ToList())),
            ]).Append(["all", .. shapes.Select(s => Cell(report.Rows.Where(r => r.Shape == s).ToList()))]));
        Terminal.Line("Indoor examples (first per source × shape × class × kind):");
        Terminal.Line();
        foreach (var e in report.Examples)
        {
            Terminal.Line($"- {e.Source} / {e.Shape} / {e.Class} / {e.Reason}: `{e.Text}`");
        }

        Terminal.Line();
        Terminal.Line($"<!-- indoor: {report.Elapsed.TotalSeconds:F1} s -->");
        return report.Rows.Where(r => r.Shape == "box" && r.Class is "interior" or "union-arm" or "outdoor-near" or "outdoor").All(r => r.Any == 0);
    }

    private static string Cell(IReadOnlyList<IndoorAccuracyRow> rows)
    {
        long n = rows.Sum(r => r.Queries), any = rows.Sum(r => r.Any);
        return n == 0 ? "—" : $"{N(any)} / {N(n)} ({Pct(any, n)})";
    }
}
