using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// Outdoor membership (facts §3): which 24 m land cells a set of spheres touches, in the global lcoord grid where
/// landblock lines are not special (facts §6.1 — the #106 freeze came from clamping to the current block).
/// </summary>
public static class OutdoorCells
{
    /// <summary>Adds the land cell at a global lcoord if it is on the map (<c>add_outside_cell</c>, facts §3.1). No same-block filter.</summary>
    /// <param name="array">The array to add to.</param>
    /// <param name="x">Global column (signed: −1 and 2040 are skipped, never wrapped).</param>
    /// <param name="y">Global row.</param>
    /// <param name="landscape">Which blocks are loaded.</param>
    /// <param name="fidelity">Retail adds unloaded cells as load hints; ACE drops them (facts §7 #2).</param>
    public static void AddOutsideCell(CellArray array, int x, int y, ILandscape landscape, OutdoorFidelity fidelity)
    {
        if (!LandDefs.InBounds(x, y))
        {
            return;
        }

        var id = LandDefs.LcoordToGid(x, y);
        bool loaded = landscape.IsLoaded(id.Landblock);
        if (loaded || !fidelity.DropUnloadedCells)
        {
            array.Add(id, loaded);
        }
    }

    /// <summary>
    /// Adds the neighbours a sphere reaches (<c>check_add_cell_boundary</c>, facts §3.2): per axis, strict comparisons,
    /// at most the 3 × 3 neighbourhood, in retail's exact call order.
    /// </summary>
    /// <param name="array">The array.</param>
    /// <param name="ptX">Centre within its cell, [0, 24).</param>
    /// <param name="ptY">Centre within its cell, [0, 24).</param>
    /// <param name="cell">The cell's global lcoord.</param>
    /// <param name="minRad">The radius r.</param>
    /// <param name="maxRad">24 − r.</param>
    /// <param name="landscape">Which blocks are loaded.</param>
    /// <param name="fidelity">Retail or ACE.</param>
    public static void CheckAddCellBoundary(CellArray array, float ptX, float ptY, Lcoord cell, float minRad, float maxRad, ILandscape landscape, OutdoorFidelity fidelity)
    {
        int x = cell.X, y = cell.Y;
        if (ptX > maxRad)
        {
            AddOutsideCell(array, x + 1, y, landscape, fidelity);
            if (ptY > maxRad)
            {
                AddOutsideCell(array, x + 1, y + 1, landscape, fidelity);
            }

            if (ptY < minRad)
            {
                AddOutsideCell(array, x + 1, y - 1, landscape, fidelity);
            }
        }

        // Not "else": when r > 12, minRad > maxRad and both x branches fire (facts §3.2).
        if (ptX < minRad)
        {
            AddOutsideCell(array, x - 1, y, landscape, fidelity);
            if (ptY > maxRad)
            {
                AddOutsideCell(array, x - 1, y + 1, landscape, fidelity);
            }

            if (ptY < minRad)
            {
                AddOutsideCell(array, x - 1, y - 1, landscape, fidelity);
            }
        }

        if (ptY > maxRad)
        {
            AddOutsideCell(array, x, y + 1, landscape, fidelity);
        }

        if (ptY < minRad)
        {
            AddOutsideCell(array, x, y - 1, landscape, fidelity);
        }
    }

    /// <summary>
    /// Collects the land cells the spheres touch (<c>add_all_outside_cells</c>, sphere variant, facts §3.3).
    /// </summary>
    /// <param name="array">The array; a no-op while its <see cref="CellArray.AddedOutside"/> latch is set, which this sets (retail).</param>
    /// <param name="position">The position's cell id: land, env or block id (env positions reach the land under them, facts §6.12).</param>
    /// <param name="origin">The position's own point (block frame), used only when there are no spheres.</param>
    /// <param name="spheres">Sphere centres in <paramref name="position"/>'s block frame; never mutated.</param>
    /// <param name="landscape">Which blocks are loaded.</param>
    /// <param name="fidelity">Retail or ACE.</param>
    public static void AddAllOutsideCells(CellArray array, CellId position, Vector3 origin, ReadOnlySpan<Sphere> spheres, ILandscape landscape, OutdoorFidelity fidelity = default)
    {
        if (array.AddedOutside)
        {
            return;
        }

        array.AddedOutside = true;
        if (spheres.IsEmpty)
        {
            // Retail works on a copy of the position (ACE mutates the caller's, facts §7 #5).
            var id = position;
            float ox = origin.X, oy = origin.Y;
            if (fidelity.Precision == OutdoorPrecision.Double)
            {
                if (OutdoorCellsDouble.OriginCell(position, origin, out var exact))
                {
                    AddOutsideCell(array, exact.X, exact.Y, landscape, fidelity);
                }
            }
            else if (LandDefs.AdjustToOutside(ref id, ref ox, ref oy) && LandDefs.GidToLcoord(id, out var only))
            {
                AddOutsideCell(array, only.X, only.Y, landscape, fidelity);
            }

            return;
        }

        if (fidelity.Precision == OutdoorPrecision.Double)
        {
            OutdoorCellsDouble.AddSpheres(array, position, spheres, landscape, fidelity);
            return;
        }

        foreach (var sphere in spheres)
        {
            var id = position;
            float cx = sphere.Center.X, cy = sphere.Center.Y;
            if (!LandDefs.AdjustToOutside(ref id, ref cx, ref cy))
            {
                break; // facts §3.3 b: a failed sphere ends the loop; cells already added stay
            }

            float ptX = InCell(cx), ptY = InCell(cy);
            LandDefs.GidToLcoord(id, out var lc);
            AddOutsideCell(array, lc.X, lc.Y, landscape, fidelity);
            CheckAddCellBoundary(array, ptX, ptY, lc, sphere.Radius, LandDefs.CellLength - sphere.Radius, landscape, fidelity);
        }
    }

    // v − 24·⌊v/24⌋ for v ∈ [0, 192): exact in double, and representable in float32.
    private static float InCell(float v) => (float)(v - (LandDefs.CellLength * Math.Floor(v / (double)LandDefs.CellLength)));
}
