using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>
/// An implementation offered with fewer operations than it has (<c>acphys serve --ops</c>), or declaring another mode:
/// every answer is the inner one, <see cref="Ops"/> is the inner set masked, an operation outside the mask throws
/// <see cref="NotSupportedException"/> as the contract allows — e.g. the reference restricted to transitions, the shape
/// of a port whose only cell query is its transition code's (issue #29) — and the declarations default to the inner
/// ones (a finding is re-judged under other declarations to name the deviation that would make it intended).
/// </summary>
/// <param name="inner">The implementation.</param>
/// <param name="mask">The operations kept.</param>
public sealed class OpsOffered(ICellPhysics inner, Op mask) : ICellPhysics, ITransport
{
    /// <inheritdoc/>
    public IReadOnlyList<string> Negotiated => Transports.Negotiated(inner);

    /// <inheritdoc/>
    /// <remarks>The inner transport's: a finding re-judged under other declarations was sent what the inner one sends.</remarks>
    public bool ScenesAsRecords => Transports.ScenesAsRecords(inner);

    /// <inheritdoc/>
    /// <remarks>Never: a run streams through the implementation itself, not through a re-declared view of it.</remarks>
    public bool Streams => false;

    /// <inheritdoc/>
    public T Streamed<T>(Func<T> run) => run();

    /// <inheritdoc/>
    public string Name =>
        inner.Name
        + ((inner.Ops & ~mask & Op.All) == 0 ? string.Empty : " (without " + string.Join(", ", OpNames.Names(inner.Ops & ~mask & Op.All)) + ")")
        + (Pick == inner.Pick && Indoor == inner.Indoor && Outdoor == inner.Outdoor ? string.Empty
            : " declaring " + string.Join("+", FidelityNames.Names(Indoor, Outdoor).Prepend(PickNames.Of(Pick))));

    /// <inheritdoc/>
    public Op Ops => inner.Ops & mask;

    /// <inheritdoc/>
    public PickPolicy Pick { get; init; } = inner.Pick;

    /// <inheritdoc/>
    public IndoorFidelity Indoor { get; init; } = inner.Indoor;

    /// <inheritdoc/>
    public OutdoorFidelity Outdoor { get; init; } = inner.Outdoor;

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => Need(Op.BlockIdToLcoord).BlockIdToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord) => Need(Op.GidToLcoord).GidToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => Need(Op.LcoordToGid).LcoordToGid(x, y);

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => Need(Op.InboundValidCellId).InboundValidCellId(id);

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => Need(Op.GetOutsideLcoord).GetOutsideLcoord(id, x, y, out lcoord);

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y) => Need(Op.AdjustToOutside).AdjustToOutside(id, x, y);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => Need(Op.OutsideCells).OutsideCells(cell, spheres);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres) => Need(Op.OutsideCells).OutsideCells(cell, origin, spheres);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => Need(Op.FindCell).FindCell(cell, spheres, current);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) => Need(Op.FindCell).FindCell(cell, origin, spheres, current);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => Need(Op.OutsideCellsParts).OutsideCellsParts(parts);

    /// <inheritdoc/>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(scene, cell, spheres, current, false);

    /// <inheritdoc/>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
        Need(loadCells ? Op.FindCellTransition : scene is null ? Op.FindCell : Op.FindCellScene).FindCell(scene, cell, spheres, current, loadCells);

    /// <inheritdoc/>
    public IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) =>
        Need(walk.LoadCells ? Op.FindCellTransition : walk.Scene is null ? Op.FindCell : Op.FindCellScene).FindCellWalk(walk);

    /// <inheritdoc/>
    public FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) =>
        Need(loadCells ? Op.FindCellPartsTransition : Op.FindCellPartsScene).FindCellParts(scene, parts, loadCells);

    /// <inheritdoc/>
    public IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) =>
        Need(loadCells ? Op.FindCellPartsTransition : Op.FindCellPartsScene).FindCellPartsWalk(scene, queries, loadCells);

    private ICellPhysics Need(Op op) =>
        (Ops & op) != 0 ? inner : throw new NotSupportedException($"{inner.Name} is offered without {OpNames.Names(op)[0]}");
}
