using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Props.Support;

/// <summary>An adapter that forwards everything to another; tests override the one behaviour they change.</summary>
/// <param name="inner">The adapter forwarded to.</param>
internal abstract class Forwarding(ICellPhysics inner) : ICellPhysics
{
    public virtual string Name => "wrapped " + Inner.Name;

    public Op Ops => Inner.Ops;

    public virtual PickPolicy Pick => Inner.Pick;

    public virtual IndoorFidelity Indoor => Inner.Indoor;

    public virtual OutdoorFidelity Outdoor => Inner.Outdoor;

    protected ICellPhysics Inner { get; } = inner;

    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => Inner.BlockIdToLcoord(id, out lcoord);

    public virtual bool GidToLcoord(CellId id, out Lcoord lcoord) => Inner.GidToLcoord(id, out lcoord);

    public CellId LcoordToGid(int x, int y) => Inner.LcoordToGid(x, y);

    public virtual bool InboundValidCellId(CellId id) => Inner.InboundValidCellId(id);

    public virtual bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => Inner.GetOutsideLcoord(id, x, y, out lcoord);

    public virtual AdjustResult AdjustToOutside(CellId id, float x, float y) => Inner.AdjustToOutside(id, x, y);

    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => Inner.OutsideCells(cell, spheres);

    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => Inner.FindCell(cell, spheres, current);

    /// <inheritdoc/>
    public virtual IReadOnlyList<CellId> OutsideCells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres) => Inner.OutsideCells(cell, origin, spheres);

    /// <inheritdoc/>
    public virtual FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) => Inner.FindCell(cell, origin, spheres, current);

    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => Inner.OutsideCellsParts(parts);

    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(scene, cell, spheres, current, false);

    public virtual FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
        Inner.FindCell(scene, cell, spheres, current, loadCells);

    public virtual FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) => Inner.FindCellParts(scene, parts, loadCells);
}
