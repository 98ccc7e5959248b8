using System.Numerics;
using AcPhys.Core;
using AcPhys.Spec.Invariants;

namespace AcPhys.Studies.Invariants;

/// <summary>
/// The outdoor query in exact rational arithmetic (<see cref="Dyadic"/>), independent of core: retail's rules
/// (EPS snap, floor, strict neighbour tests in retail's call order, closed squares, last hit wins, facts §2.1, §3, §4)
/// with no rounding anywhere. The ground truth the float32 and double modes are measured against.
/// </summary>
public static class ExactOutdoor
{
    private static readonly Dyadic CellSide = Dyadic.Of(24);

    /// <summary>Returns the land cells the spheres touch, in retail insertion order (every block loaded).</summary>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="spheres">Centres in its block frame; radii must be finite.</param>
    /// <returns>The cells, or null when a radius is not finite (the oracle does not model IEEE infinities).</returns>
    public static List<CellId>? OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => OutsideCells(cell, Vector3.Zero, spheres);

    /// <summary>Returns the land cells the spheres touch, or with no spheres the position's own cell (facts §3.3 step 3).</summary>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="origin">The position's point in its block frame (read only when there are no spheres).</param>
    /// <param name="spheres">Centres in its block frame; radii must be finite.</param>
    /// <returns>The cells, or null when a radius is not finite.</returns>
    public static List<CellId>? OutsideCells(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres)
    {
        var cells = new List<CellId>();
        if (spheres.Any(s => !float.IsFinite(s.Radius)))
        {
            return null;
        }

        if (spheres.Count == 0)
        {
            if (Column(cell, origin.X, origin.Y) is var (ox, oy, _, _))
            {
                Add(cells, ox, oy);
            }

            return cells;
        }

        foreach (var s in spheres)
        {
            if (Column(cell, s.Center.X, s.Center.Y) is not var (gx, gy, px, py))
            {
                break; // facts §3.3 b: a sphere off the map ends the loop
            }

            Add(cells, gx, gy);
            var r = Dyadic.Of(s.Radius);
            var maxRad = CellSide - r;
            bool east = px > maxRad, west = px < r, north = py > maxRad, south = py < r;
            if (east)
            {
                Add(cells, gx + 1, gy);
                AddIf(north, cells, gx + 1, gy + 1);
                AddIf(south, cells, gx + 1, gy - 1);
            }

            if (west)
            {
                Add(cells, gx - 1, gy);
                AddIf(north, cells, gx - 1, gy + 1);
                AddIf(south, cells, gx - 1, gy - 1);
            }

            AddIf(north, cells, gx, gy + 1);
            AddIf(south, cells, gx, gy - 1);
        }

        return cells;
    }

    /// <summary>Returns the retail pick over candidates: the last land cell whose closed square contains the (unsnapped) centre.</summary>
    /// <param name="cell">The position's cell id (the centre's frame).</param>
    /// <param name="center">Sphere 0's centre.</param>
    /// <param name="candidates">Candidates in insertion order.</param>
    /// <returns>The pick, or <see cref="CellId.None"/>.</returns>
    public static CellId Pick(CellId cell, Vector3 center, IReadOnlyList<CellId> candidates)
    {
        var pick = CellId.None;
        foreach (var id in candidates)
        {
            if (OutdoorInvariants.SquareContains(cell, id, center))
            {
                pick = id;
            }
        }

        return pick;
    }

    /// <summary>Returns the cells and the retail pick of an outdoor query.</summary>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="spheres">The spheres.</param>
    /// <returns>The cells and the pick, or null when a radius is not finite.</returns>
    public static (List<CellId> Cells, CellId Containing)? FindCell(CellId cell, IReadOnlyList<Sphere> spheres) => FindCell(cell, Vector3.Zero, spheres);

    /// <summary>Returns the cells and the retail pick of an outdoor query from a land position.</summary>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="origin">The position's point (read only when there are no spheres).</param>
    /// <param name="spheres">The spheres.</param>
    /// <returns>The cells and the pick, or null when a radius is not finite.</returns>
    public static (List<CellId> Cells, CellId Containing)? FindCell(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres)
    {
        var cells = OutsideCells(cell, origin, spheres);
        if (cells is null)
        {
            return null;
        }

        return (cells, spheres.Count == 0 ? CellId.None : Pick(cell, spheres[0].Center, cells));
    }

    /// <summary>
    /// Returns the global lcoord of the column under a snapped block-frame point and the exact point within that
    /// cell, or null when the id is malformed, the point not finite, or the column off the map (AdjustToOutside fails).
    /// </summary>
    /// <param name="cell">The id naming the block.</param>
    /// <param name="x">Block-frame x.</param>
    /// <param name="y">Block-frame y.</param>
    /// <returns>(gx, gy, px, py) or null.</returns>
    public static (long Gx, long Gy, Dyadic Px, Dyadic Py)? Column(CellId cell, float x, float y)
    {
        if (!Oracle.LowInRange(cell.Low) || !Oracle.BlockOnMap(cell) || !float.IsFinite(x) || !float.IsFinite(y))
        {
            return null;
        }

        Dyadic dx = Dyadic.Of(Oracle.Snap(x)), dy = Dyadic.Of(Oracle.Snap(y));
        BigInteger kx = dx.FloorDiv(24), ky = dy.FloorDiv(24);
        BigInteger gx = (8 * (long)cell.BlockX) + kx, gy = (8 * (long)cell.BlockY) + ky;
        if (gx < 0 || gx >= Oracle.MapCells || gy < 0 || gy >= Oracle.MapCells)
        {
            return null;
        }

        return ((long)gx, (long)gy, dx - new Dyadic(kx * CellSide.Units), dy - new Dyadic(ky * CellSide.Units));
    }

    private static void AddIf(bool condition, List<CellId> cells, long x, long y)
    {
        if (condition)
        {
            Add(cells, x, y);
        }
    }

    private static void Add(List<CellId> cells, long x, long y)
    {
        if (Oracle.OnMap(x, y) && Oracle.CellOf((int)x, (int)y) is var id && !cells.Contains(id))
        {
            cells.Add(id);
        }
    }
}
