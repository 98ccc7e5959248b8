using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Props.Support;

/// <summary>
/// A port whose find_cell and parts answers are another's, each rewritten (a port bug that only reorders, or only adds a cell); a
/// whole walk is answered by the inner port (an array that lives for the walk is kept) and rewritten answer by answer.
/// </summary>
/// <param name="inner">The port whose answers are rewritten.</param>
/// <param name="rewrite">The rewrite.</param>
internal sealed class RewrittenAnswers(ICellPhysics inner, Func<FindCellResult, FindCellResult> rewrite) : Forwarding(inner), ICellPhysics
{
    /// <summary>Gets the indoor deviations declared instead of the inner port's, if any.</summary>
    public IndoorFidelity? Declares { get; init; }

    public override IndoorFidelity Indoor => Declares ?? Inner.Indoor;

    /// <summary>Reverses the candidates (and their load-hint flags) of an answer with two or more.</summary>
    /// <param name="r">The answer.</param>
    /// <returns>The answer reordered: the same cells, containing cell and flags.</returns>
    public static FindCellResult Reversed(FindCellResult r) =>
        r.Cells.Count < 2 ? r : new FindCellResult([.. r.Cells.Reverse()], r.Containing) { Loaded = r.Loaded?.Reverse().ToArray(), HitsInteriorCell = r.HitsInteriorCell };

    /// <summary>Appends a land cell at the map's far corner (never a candidate of a generated query, so never stale).</summary>
    /// <param name="r">The answer.</param>
    /// <returns>The answer with one extra cell.</returns>
    public static FindCellResult WithExtraCell(FindCellResult r) =>
        r.Cells.Count == 0 ? r : new FindCellResult([.. r.Cells, new CellId(0x00000001)], r.Containing) { Loaded = r.Loaded is { } l ? [.. l, true] : null, HitsInteriorCell = r.HitsInteriorCell };

    public override FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) =>
        rewrite(Inner.FindCell(cell, origin, spheres, current));

    public override FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
        rewrite(Inner.FindCell(scene, cell, spheres, current, loadCells));

    public override FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) =>
        rewrite(Inner.FindCellParts(scene, parts, loadCells));

    public IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) => [.. Inner.FindCellWalk(walk).Select(rewrite)];

    public IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) =>
        [.. Inner.FindCellPartsWalk(scene, queries, loadCells).Select(rewrite)];
}
