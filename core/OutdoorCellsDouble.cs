using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// The outdoor sphere loop of <see cref="OutdoorCells.AddAllOutsideCells"/> in the double-precision reference
/// (<see cref="OutdoorPrecision.Double"/>): the same rules and call order, with the re-base, the in-cell point and
/// the neighbour tests exact for float32 inputs.
/// </summary>
internal static class OutdoorCellsDouble
{
    /// <summary>Adds the cells of every sphere, stopping at the first whose centre is off the map (facts §3.3 b).</summary>
    /// <param name="array">The array.</param>
    /// <param name="position">The position's cell id.</param>
    /// <param name="spheres">Centres in the position's block frame.</param>
    /// <param name="landscape">Which blocks are loaded.</param>
    /// <param name="fidelity">Retail or ACE.</param>
    public static void AddSpheres(CellArray array, CellId position, ReadOnlySpan<Sphere> spheres, ILandscape landscape, OutdoorFidelity fidelity)
    {
        foreach (var sphere in spheres)
        {
            var id = position;
            double cx = sphere.Center.X, cy = sphere.Center.Y;
            if (!LandDefs.AdjustToOutsideInDouble(ref id, ref cx, ref cy))
            {
                break;
            }

            LandDefs.GidToLcoord(id, out var lc);
            OutdoorCells.AddOutsideCell(array, lc.X, lc.Y, landscape, fidelity);
            AddNeighbours(array, InCell(cx), InCell(cy), lc, sphere.Radius, landscape, fidelity);
        }
    }

    /// <summary>Returns the first point of a position with no spheres, re-seated in double.</summary>
    /// <param name="position">The position's id.</param>
    /// <param name="origin">Its point.</param>
    /// <param name="lcoord">The cell's lcoord.</param>
    /// <returns>False when off the map.</returns>
    public static bool OriginCell(CellId position, Vector3 origin, out Lcoord lcoord)
    {
        double ox = origin.X, oy = origin.Y;
        lcoord = default;
        return LandDefs.AdjustToOutsideInDouble(ref position, ref ox, ref oy) && LandDefs.GidToLcoord(position, out lcoord);
    }

    // check_add_cell_boundary with p > 24 − r written as (p − 24) > −r: p − 24 is exact in double (p has at most
    // 44 significant bits), so the strict tests are exact where retail's float32 24 − r rounds (facts §3.2).
    private static void AddNeighbours(CellArray array, double ptX, double ptY, Lcoord cell, double r, ILandscape landscape, OutdoorFidelity fidelity)
    {
        bool east = ptX - LandDefs.CellLength > -r, west = ptX < r;
        bool north = ptY - LandDefs.CellLength > -r, south = ptY < r;
        int x = cell.X, y = cell.Y;
        if (east)
        {
            OutdoorCells.AddOutsideCell(array, x + 1, y, landscape, fidelity);
            if (north)
            {
                OutdoorCells.AddOutsideCell(array, x + 1, y + 1, landscape, fidelity);
            }

            if (south)
            {
                OutdoorCells.AddOutsideCell(array, x + 1, y - 1, landscape, fidelity);
            }
        }

        if (west)
        {
            OutdoorCells.AddOutsideCell(array, x - 1, y, landscape, fidelity);
            if (north)
            {
                OutdoorCells.AddOutsideCell(array, x - 1, y + 1, landscape, fidelity);
            }

            if (south)
            {
                OutdoorCells.AddOutsideCell(array, x - 1, y - 1, landscape, fidelity);
            }
        }

        if (north)
        {
            OutdoorCells.AddOutsideCell(array, x, y + 1, landscape, fidelity);
        }

        if (south)
        {
            OutdoorCells.AddOutsideCell(array, x, y - 1, landscape, fidelity);
        }
    }

    private static double InCell(double v) => v - (LandDefs.CellLength * Math.Floor(v / LandDefs.CellLength));
}
