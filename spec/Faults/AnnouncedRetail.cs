using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// An implementation that behaves in one mode and announces retail (<c>acphys serve --announce-retail</c>, the planted fault <c>ace-announced-retail</c>): a port that
/// deviates without declaring it. Every answer is the inner one; only the declared pick and fidelity say retail, so the
/// suite compares it with retail and must find each deviation (docs/facts-coverage.md, "Declared deviations").
/// </summary>
/// <param name="inner">The implementation whose answers are served.</param>
internal sealed class AnnouncedRetail(ICellPhysics inner) : ICellPhysics
{
    /// <inheritdoc/>
    public string Name => inner.Name + " (announced retail)";

    /// <inheritdoc/>
    public Op Ops => inner.Ops;

    /// <inheritdoc/>
    public PickPolicy Pick => PickPolicy.Retail;

    /// <inheritdoc/>
    public IndoorFidelity Indoor => IndoorFidelity.Retail;

    /// <inheritdoc/>
    public OutdoorFidelity Outdoor => OutdoorFidelity.Retail;

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => inner.BlockIdToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord) => inner.GidToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => inner.LcoordToGid(x, y);

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => inner.InboundValidCellId(id);

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => inner.GetOutsideLcoord(id, x, y, out lcoord);

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y) => inner.AdjustToOutside(id, x, y);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => inner.OutsideCells(cell, spheres);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres) => inner.OutsideCells(cell, origin, spheres);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => inner.FindCell(cell, spheres, current);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) => inner.FindCell(cell, origin, spheres, current);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => inner.OutsideCellsParts(parts);

    /// <inheritdoc/>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => inner.FindCell(scene, cell, spheres, current);

    /// <inheritdoc/>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) => inner.FindCell(scene, cell, spheres, current, loadCells);

    /// <inheritdoc/>
    public IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) => inner.FindCellWalk(walk);

    /// <inheritdoc/>
    public FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) => inner.FindCellParts(scene, parts, loadCells);
}
