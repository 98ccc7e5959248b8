using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A port that keeps one world frame, with a shim bug (the planted fault <c>world-frame-swapped-axes</c>; docs/protocol.md,
/// "World frame"): every block-frame point it is asked about goes to the world frame and back, and the way back takes
/// the block origin as (192 · block y, 192 · block x) — the id's two block bytes read the wrong way round. x becomes
/// (float)((192 · bx + x) − 192 · by), y likewise, in double: bit for bit what a world-frame server with that shim gets
/// from the tool's exact world coordinates. The points are the ones a world-frame request carries (sphere centres and
/// <c>origin</c> framed in the request's cell, the x/y of get_outside_lcoord and adjust_to_outside, each part's origin
/// framed in its own cell); z, radii and answers are the inner implementation's. A block with bx = by is unharmed.
/// </summary>
/// <param name="inner">The implementation behind the shim.</param>
internal sealed class SwappedOriginShim(ICellPhysics inner) : ForwardingPhysics(inner)
{
    /// <inheritdoc/>
    public override string Name => Inner.Name + " (world-frame shim, block axes swapped)";

    /// <inheritdoc/>
    public override bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => Inner.GetOutsideLcoord(id, X(id, x), Y(id, y), out lcoord);

    /// <inheritdoc/>
    public override AdjustResult AdjustToOutside(CellId id, float x, float y) => Inner.AdjustToOutside(id, X(id, x), Y(id, y));

    /// <inheritdoc/>
    public override IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => Inner.OutsideCells(cell, Shifted(cell, spheres));

    /// <inheritdoc/>
    public override IReadOnlyList<CellId> OutsideCells(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres) => Inner.OutsideCells(cell, Point(cell, origin), Shifted(cell, spheres));

    /// <inheritdoc/>
    public override FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => Inner.FindCell(cell, Shifted(cell, spheres), current);

    /// <inheritdoc/>
    public override FindCellResult FindCell(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) => Inner.FindCell(cell, Point(cell, origin), Shifted(cell, spheres), current);

    /// <inheritdoc/>
    public override IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => Inner.OutsideCellsParts(Shifted(parts));

    /// <inheritdoc/>
    public override FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) => Inner.FindCellParts(scene, Shifted(parts), loadCells);

    /// <inheritdoc/>
    public override IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) =>
        Inner.FindCellPartsWalk(scene, [.. queries.Select(q => (IReadOnlyList<Part>)Shifted(q))], loadCells);

    /// <inheritdoc/>
    public override FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => Inner.FindCell(scene, cell, Shifted(cell, spheres), current);

    /// <inheritdoc/>
    public override FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) => Inner.FindCell(scene, cell, Shifted(cell, spheres), current, loadCells);

    // A world-frame port is asked query by query (a world-frame server announces no find_cell_walk): the walk steps
    // through this shim's own queries, as ICellPhysics.FindCellWalk's default does.
    /// <inheritdoc/>
    public override IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) => WalkThread.AskEach(this, walk);

    // The world value is exact in double (192 · block + a float); the way back subtracts the other axis's origin.
    private static float Back(float v, double there, double back) => float.IsFinite(v) ? (float)((there + v) - back) : v;

    private static float X(CellId cell, float x) => Back(x, 192.0 * cell.BlockX, 192.0 * cell.BlockY);

    private static float Y(CellId cell, float y) => Back(y, 192.0 * cell.BlockY, 192.0 * cell.BlockX);

    private static Vector3 Point(CellId cell, Vector3 p) => new(X(cell, p.X), Y(cell, p.Y), p.Z);

    private static Part[] Shifted(IReadOnlyList<Part> parts) => [.. parts.Select(p => p with { Frame = p.Frame with { Origin = Point(p.Cell, p.Frame.Origin) } })];

    private static Sphere[] Shifted(CellId cell, IReadOnlyList<Sphere> spheres) => [.. spheres.Select(s => s with { Center = Point(cell, s.Center) })];
}
