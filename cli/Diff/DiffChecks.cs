using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Cli.Diff;

/// <summary>
/// The differential checks of <c>acphys diff</c>, written as invariants ("the implementation answers like the
/// reference") so they run, shrink and replay through the same FsCheck runner as the catalogue. Each compares only
/// ops both sides offer; the reference uses the pick policy the implementation declares.
/// </summary>
/// <param name="reference">The reference to compare with.</param>
internal sealed class DiffChecks(ICellPhysics reference)
{
    /// <summary>Gets every check, in the order they run.</summary>
    public IReadOnlyList<Invariant> All =>
    [
        new Invariant<LandCase>("DIFF-LANDDEFS", "Every LandDefs op the implementation offers answers every generated case like the reference.", "differential", Op.None, LandDomain.Instance, Land),
        new Invariant<OutdoorCase>("DIFF-OUTSIDE-CELLS", "outside_cells gives the reference's cells in the reference's insertion order.", "differential", Op.OutsideCells, OutdoorDomain.Instance, OutsideCells),
        new Invariant<OutdoorCase>("DIFF-FIND-CELL", "find_cell on open land gives the reference's cells and containing cell (no current cell).", "differential", Op.FindCell, OutdoorDomain.Instance, FindCell),
        new Invariant<Walk>("DIFF-WALK", "Along a generated walk, every step's find_cell answer (cells and containing cell, with the current cell carried) is the reference's.", "differential", Op.FindCell, WalkDomain.Instance, WalkCheck),
        new Invariant<PartsCase>("DIFF-PARTS", "outside_cells_parts gives the reference's cells in order.", "differential", Op.OutsideCellsParts, PartsDomain.Instance, Parts),
    ];

    private Outcome Land(ICellPhysics impl, LandCase c)
    {
        var ops = impl.Ops & Op.LandDefs;
        if (ops == Op.None)
        {
            return Outcome.Vacuous;
        }

        var mine = Answers.Land(impl, c, ops);
        var theirs = Answers.Land(reference, c, ops);
        for (int i = 0; i < mine.Count; i++)
        {
            if (mine[i].Answer != theirs[i].Answer)
            {
                return Outcome.Violated($"{mine[i].Call}: implementation {mine[i].Answer} | reference {theirs[i].Answer}");
            }
        }

        return Outcome.Holds;
    }

    private Outcome OutsideCells(ICellPhysics impl, OutdoorCase q)
    {
        string mine = Answers.Cells(impl.OutsideCells(q.Cell, q.Spheres));
        string theirs = Answers.Cells(reference.OutsideCells(q.Cell, q.Spheres));
        return mine == theirs ? Outcome.Holds : Outcome.Violated($"outside_cells: implementation {mine} | reference {theirs}");
    }

    private Outcome FindCell(ICellPhysics impl, OutdoorCase q)
    {
        var a = impl.FindCell(q.Cell, q.Spheres, default);
        var b = reference.FindCell(q.Cell, q.Spheres, default);
        string mine = Answers.Cells(a.Cells, a.Containing), theirs = Answers.Cells(b.Cells, b.Containing);
        return mine == theirs ? Outcome.Holds : Outcome.Violated($"find_cell: implementation {mine} | reference {theirs}");
    }

    private Outcome WalkCheck(ICellPhysics impl, Walk walk)
    {
        var mine = WalkRunner.Run(impl, walk);
        var theirs = WalkRunner.Run(reference, walk);
        for (int i = 0; i < Math.Min(mine.Count, theirs.Count); i++)
        {
            string a = Answers.Cells(mine[i].Cells, mine[i].Containing), b = Answers.Cells(theirs[i].Cells, theirs[i].Containing);
            if (a != b)
            {
                return Outcome.Violated($"step {i}: implementation {a} | reference {b}");
            }
        }

        return Outcome.Holds;
    }

    private Outcome Parts(ICellPhysics impl, PartsCase c)
    {
        string mine = Answers.Cells(impl.OutsideCellsParts(c.Parts)), theirs = Answers.Cells(reference.OutsideCellsParts(c.Parts));
        return mine == theirs ? Outcome.Holds : Outcome.Violated($"outside_cells_parts: implementation {mine} | reference {theirs}");
    }
}
