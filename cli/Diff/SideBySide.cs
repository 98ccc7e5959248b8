using System.Text;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Cli.Diff;

/// <summary>The two answers to a diverging input, side by side: one row per op (a land case) or per step (a walk).</summary>
internal static class SideBySide
{
    /// <summary>Builds the rows for a diverging case.</summary>
    /// <param name="c">The case (LandCase, OutdoorCase, Walk or PartsCase).</param>
    /// <param name="impl">The implementation.</param>
    /// <param name="reference">The reference.</param>
    /// <returns>(what was asked, implementation's answer, reference's answer) rows.</returns>
    public static IReadOnlyList<(string Query, string Implementation, string Reference)> Rows(object? c, ICellPhysics impl, ICellPhysics reference)
    {
        switch (c)
        {
            case LandCase land:
                {
                    var ops = impl.Ops & Op.LandDefs;
                    var a = Answers.Land(impl, land, ops);
                    var b = Answers.Land(reference, land, ops);
                    return a.Zip(b, (x, y) => (x.Call, x.Answer, y.Answer)).ToArray();
                }

            case OutdoorCase q:
                {
                    var rows = new List<(string, string, string)>();
                    if ((impl.Ops & Op.OutsideCells) != 0)
                    {
                        rows.Add(("outside_cells", Answers.Ask(() => Answers.Cells(impl.OutsideCells(q.Cell, q.Origin, q.Spheres))), Answers.Cells(reference.OutsideCells(q.Cell, q.Origin, q.Spheres))));
                    }

                    if ((impl.Ops & Op.FindCell) != 0)
                    {
                        var y = reference.FindCell(q.Cell, q.Origin, q.Spheres, default);
                        rows.Add(("find_cell", Answers.Ask(() =>
                        {
                            var x = impl.FindCell(q.Cell, q.Origin, q.Spheres, default);
                            return Answers.Cells(x.Cells, x.Containing);
                        }), Answers.Cells(y.Cells, y.Containing)));
                    }

                    return rows;
                }

            case Walk walk:
                {
                    var b = WalkRunner.Run(reference, walk);
                    if (!Answers.TryAsk(() => WalkRunner.Run(impl, walk), out var a, out string? threw))
                    {
                        return [("the walk", threw, $"{b.Count} steps answered")];
                    }

                    return a.Zip(b, (x, y) => (
                        $"step {x.Index}: find_cell({x.Frame}, ({Answers.Float(x.Position.X)}, {Answers.Float(x.Position.Y)}), current {(x.Index == 0 ? "none" : a[x.Index - 1].Current.ToString())})",
                        Answers.Cells(x.Cells, x.Containing),
                        Answers.Cells(y.Cells, y.Containing))).ToArray();
                }

            case SceneWalk sw:
                {
                    var scene = DiffChecks.SceneSent(impl, sw);
                    var rows = new List<(string, string, string)>();
                    foreach (bool loadCells in (impl.Ops & Op.FindCellTransition) != 0 ? [false, true] : new[] { false })
                    {
                        if (!Answers.TryAsk(() => SceneWalkRunner.Run(impl, sw, loadCells), out var trace, out string? threw))
                        {
                            rows.Add(("the walk", threw, string.Empty));
                            continue;
                        }

                        foreach (var s in trace)
                        {
                            var current = s.Index == 0 ? CellId.None : trace[s.Index - 1].Current;
                            var want = reference.FindCell(scene, s.Query.Cell, s.Query.Spheres, current, loadCells);
                            rows.Add((
                                $"step {s.Index} {(loadCells ? "transition" : "static")}: find_cell({s.Frame}, ({Answers.Float(s.Position.X)}, {Answers.Float(s.Position.Y)}, {Answers.Float(s.Position.Z)}), current {(current.IsNone ? "none" : current.ToString())})",
                                Answers.Cells(s.Answer!.Cells, s.Answer.Containing),
                                Answers.Cells(want.Cells, want.Containing)));
                        }
                    }

                    return rows;
                }

            case PartsCase parts:
                return [("outside_cells_parts", Answers.Ask(() => Answers.Cells(impl.OutsideCellsParts(parts.Parts))), Answers.Cells(reference.OutsideCellsParts(parts.Parts)))];

            default:
                return [];
        }
    }

    /// <summary>Renders rows as a markdown table, marking the rows that differ.</summary>
    /// <param name="rows">The rows.</param>
    /// <param name="implName">The implementation's name.</param>
    /// <returns>The table.</returns>
    public static string Markdown(IReadOnlyList<(string Query, string Implementation, string Reference)> rows, string implName)
    {
        var md = new StringBuilder();
        md.Append($"| query | {implName} | reference | |\n|---|---|---|---|\n");
        foreach (var (query, mine, theirs) in rows)
        {
            md.Append($"| `{query}` | {mine} | {theirs} | {(mine == theirs ? string.Empty : "**differs**")} |\n");
        }

        return md.ToString();
    }
}
