using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// An implementation that forwards every member of <see cref="ICellPhysics"/> to another; the planted faults that wrap an
/// implementation (a shim, a false announcement, one defective op) override only what they change, so a new op is
/// forwarded here once.
/// </summary>
/// <param name="inner">The implementation forwarded to.</param>
internal abstract class ForwardingPhysics(ICellPhysics inner) : ICellPhysics
{
    /// <inheritdoc/>
    public virtual string Name => Inner.Name;

    /// <inheritdoc/>
    public virtual Op Ops => Inner.Ops;

    /// <inheritdoc/>
    public virtual PickPolicy Pick => Inner.Pick;

    /// <inheritdoc/>
    public virtual IndoorFidelity Indoor => Inner.Indoor;

    /// <inheritdoc/>
    public virtual OutdoorFidelity Outdoor => Inner.Outdoor;

    /// <summary>Gets the implementation forwarded to.</summary>
    protected ICellPhysics Inner { get; } = inner;

    /// <inheritdoc/>
    public virtual bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => Inner.BlockIdToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public virtual bool GidToLcoord(CellId id, out Lcoord lcoord) => Inner.GidToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public virtual CellId LcoordToGid(int x, int y) => Inner.LcoordToGid(x, y);

    /// <inheritdoc/>
    public virtual bool InboundValidCellId(CellId id) => Inner.InboundValidCellId(id);

    /// <inheritdoc/>
    public virtual bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => Inner.GetOutsideLcoord(id, x, y, out lcoord);

    /// <inheritdoc/>
    public virtual AdjustResult AdjustToOutside(CellId id, float x, float y) => Inner.AdjustToOutside(id, x, y);

    /// <inheritdoc/>
    public virtual IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => Inner.OutsideCells(cell, spheres);

    /// <inheritdoc/>
    public virtual IReadOnlyList<CellId> OutsideCells(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres) => Inner.OutsideCells(cell, origin, spheres);

    /// <inheritdoc/>
    public virtual FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => Inner.FindCell(cell, spheres, current);

    /// <inheritdoc/>
    public virtual FindCellResult FindCell(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) => Inner.FindCell(cell, origin, spheres, current);

    /// <inheritdoc/>
    public virtual IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => Inner.OutsideCellsParts(parts);

    /// <inheritdoc/>
    public virtual FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => Inner.FindCell(scene, cell, spheres, current);

    /// <inheritdoc/>
    public virtual FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) => Inner.FindCell(scene, cell, spheres, current, loadCells);

    /// <inheritdoc/>
    public virtual IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) => Inner.FindCellWalk(walk);

    /// <inheritdoc/>
    public virtual FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) => Inner.FindCellParts(scene, parts, loadCells);

    /// <inheritdoc/>
    public virtual IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) => Inner.FindCellPartsWalk(scene, queries, loadCells);
}
