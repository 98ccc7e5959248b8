using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Dat;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Cli.Diff;

/// <summary>
/// The differential checks of <c>acphys diff</c>. Each compares only ops both sides offer, the reference using the
/// pick policy the implementation declares, and names every diverging input's class: the op, the shape of the
/// difference (<see cref="CellsDelta"/>) and the input's boundary class.
/// </summary>
/// <param name="reference">The reference to compare with.</param>
internal sealed class DiffChecks(ICellPhysics reference)
{
    /// <summary>Gets every check, in the order they run.</summary>
    public IReadOnlyList<DiffCheck> All =>
    [
        new DiffCheck<LandCase>("DIFF-LANDDEFS", "Every LandDefs op the implementation offers answers every generated case like the reference.", Op.None, LandDomain.Instance, Land),
        new DiffCheck<OutdoorCase>("DIFF-OUTSIDE-CELLS", "outside_cells gives the reference's cells in the reference's insertion order.", Op.OutsideCells, OutdoorDomain.Instance, OutsideCells),
        new DiffCheck<OutdoorCase>("DIFF-FIND-CELL", "find_cell on open land gives the reference's cells and containing cell (no current cell).", Op.FindCell, OutdoorDomain.Instance, FindCell),
        new DiffCheck<Walk>("DIFF-WALK", "Along a generated walk, every step's find_cell answer (cells and containing cell, with the current cell carried) is the reference's.", Op.FindCell, WalkDomain.Instance, WalkCheck),
        new DiffCheck<PartsCase>("DIFF-PARTS", "outside_cells_parts gives the reference's cells in order.", Op.OutsideCellsParts, PartsDomain.Instance, Parts),
        new DiffCheck<SceneWalk>("DIFF-SCENE-WALK", "Along a generated walk through a generated scene (buildings, portals, dungeons), every step's find_cell answer is the reference's, asked statically and, when offered, as a movement transition.", Op.FindCellScene, SceneDomain.Instance, SceneWalkCheck),
    ];

    private Divergence? Land(ICellPhysics impl, LandCase c)
    {
        var ops = impl.Ops & Op.LandDefs;
        var mine = Answers.Land(impl, c, ops);
        var theirs = Answers.Land(reference, c, ops);
        for (int i = 0; i < mine.Count; i++)
        {
            var (call, a) = mine[i];
            string b = theirs[i].Answer;
            if (a != b)
            {
                string shape = a.StartsWith(Answers.Threw, StringComparison.Ordinal) ? a
                    : a == "fail" ? "implementation fails, reference answers"
                    : b == "fail" ? "implementation answers, reference fails"
                    : "other answer";
                return new Divergence($"{call[..call.IndexOf('(', StringComparison.Ordinal)]}: {shape}", LandDomain.Instance.Primary(c), $"{call}: implementation {a} | reference {b}");
            }
        }

        return null;
    }

    private Divergence? OutsideCells(ICellPhysics impl, OutdoorCase q)
    {
        var theirs = reference.OutsideCells(q.Cell, q.Origin, q.Spheres);
        if (!Answers.TryAsk(() => impl.OutsideCells(q.Cell, q.Origin, q.Spheres), out var mine, out string? threw))
        {
            return new Divergence("outside_cells: " + threw, OutdoorDomain.Instance.Primary(q), $"outside_cells: implementation {threw} | reference {Answers.Cells(theirs)}");
        }

        return CellsDelta.Of(mine, theirs, q.Cell) is string shape
            ? new Divergence("outside_cells: " + shape, OutdoorDomain.Instance.Primary(q), $"outside_cells: implementation {Answers.Cells(mine)} | reference {Answers.Cells(theirs)}")
            : null;
    }

    private Divergence? FindCell(ICellPhysics impl, OutdoorCase q)
    {
        var b = reference.FindCell(q.Cell, q.Origin, q.Spheres, default);
        string theirs = Answers.Cells(b.Cells, b.Containing);
        if (!Answers.TryAsk(() => impl.FindCell(q.Cell, q.Origin, q.Spheres, default), out var a, out string? threw))
        {
            return new Divergence("find_cell: " + threw, OutdoorDomain.Instance.Primary(q), $"find_cell: implementation {threw} | reference {theirs}");
        }

        return CellsDelta.Class(CellsDelta.Of(a.Cells, b.Cells, q.Cell), CellsDelta.Containing(a.Containing, b.Containing)) is string shape
            ? new Divergence("find_cell: " + shape, OutdoorDomain.Instance.Primary(q), $"find_cell: implementation {Answers.Cells(a.Cells, a.Containing)} | reference {theirs}")
            : null;
    }

    private Divergence? WalkCheck(ICellPhysics impl, Walk walk)
    {
        var theirs = WalkRunner.Run(reference, walk);
        string input = WalkDomain.Instance.Primary(walk);
        if (!Answers.TryAsk(() => WalkRunner.Run(impl, walk), out var mine, out string? threw))
        {
            return new Divergence("find_cell along the walk: " + threw, input, $"implementation {threw}");
        }

        for (int i = 0; i < Math.Min(mine.Count, theirs.Count); i++)
        {
            var (a, b) = (mine[i], theirs[i]);
            if (CellsDelta.Class(CellsDelta.Of(a.Cells, b.Cells, b.Frame), CellsDelta.Containing(a.Containing, b.Containing)) is string shape)
            {
                return new Divergence(
                    "find_cell along the walk: " + shape,
                    input,
                    $"step {i} ({StepKind(theirs, i)}): implementation {Answers.Cells(a.Cells, a.Containing)} | reference {Answers.Cells(b.Cells, b.Containing)}");
            }
        }

        return null;
    }

    private Divergence? Parts(ICellPhysics impl, PartsCase c)
    {
        var theirs = reference.OutsideCellsParts(c.Parts);
        string input = PartsDomain.Instance.Primary(c);
        if (!Answers.TryAsk(() => impl.OutsideCellsParts(c.Parts), out var mine, out string? threw))
        {
            return new Divergence("outside_cells_parts: " + threw, input, $"outside_cells_parts: implementation {threw} | reference {Answers.Cells(theirs)}");
        }

        var home = c.Parts.Count > 0 ? c.Parts[0].Cell : CellId.None;
        return CellsDelta.Of(mine, theirs, home) is string shape
            ? new Divergence("outside_cells_parts: " + shape, input, $"outside_cells_parts: implementation {Answers.Cells(mine)} | reference {Answers.Cells(theirs)}")
            : null;
    }

    // Every step of the implementation's own walk is asked of the reference with the same cell, spheres and current cell
    // (as FIND-CELL-CONFORMANCE does), in the scene as the implementation received it; a numerical tie (a probe a few
    // ulps away answers like the implementation) is not a divergence, so a correct port in other float order is clean.
    private Divergence? SceneWalkCheck(ICellPhysics impl, SceneWalk w)
    {
        var scene = SceneSent(impl, w);
        string input = SceneDomain.Instance.Primary(w);
        foreach (bool loadCells in (impl.Ops & Op.FindCellTransition) != 0 ? [false, true] : new[] { false })
        {
            string kind = loadCells ? "transition" : "static";
            if (!Answers.TryAsk(() => SceneWalkRunner.Run(impl, w, loadCells), out var trace, out string? threw))
            {
                return new Divergence($"{kind} find_cell in a scene: {threw}", input, $"implementation {threw}");
            }

            for (int i = 0; i < trace.Count; i++)
            {
                var s = trace[i];
                var current = i == 0 ? CellId.None : trace[i - 1].Current;
                var want = reference.FindCell(scene, s.Query.Cell, s.Query.Spheres, current, loadCells);
                if (SceneDelta.Of(s.Answer!, want, s.Query.Cell) is string shape
                    && Conformance.Probes(s.Query.Spheres).All(p => SceneDelta.Of(s.Answer!, reference.FindCell(scene, s.Query.Cell, p, current, loadCells), s.Query.Cell) is not null))
                {
                    return new Divergence(
                        $"{kind} find_cell in a scene: {shape}",
                        input,
                        $"step {i} ({kind}, from {s.Query.Cell}, current {current}): implementation {Answers.Cells(s.Answer!.Cells, s.Answer.Containing)} | reference {Answers.Cells(want.Cells, want.Containing)}");
                }
            }
        }

        return null;
    }

    /// <summary>Returns the scene as the implementation received it: read back from dat records when it takes them (float32 vertices).</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="w">The scene walk.</param>
    /// <returns>The scene.</returns>
    public static Scene SceneSent(ICellPhysics impl, SceneWalk w) => Transports.ScenesAsRecords(impl) ? DatRoundTrip.Of(w.Scene) : w.Scene;

    // Where along the reference's own walk the first divergence falls: what kind of step the reference took there.
    private static string StepKind(IReadOnlyList<WalkStep> theirs, int i)
    {
        if (i == 0)
        {
            return "the start";
        }

        CellId before = theirs[i - 1].Current, after = theirs[i].Current;
        return before.Landblock != after.Landblock ? "a step across a block line"
            : before != after ? "a step across a cell line"
            : "a step within a cell";
    }
}
