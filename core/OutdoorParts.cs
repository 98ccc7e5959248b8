using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// The parts / bounding-box variant of add_all_outside_cells and add_cell_block (facts §3.4), retail semantics:
/// the first part is the anchor, one add_cell_block call over the range that covers the anchor's cell and every part,
/// no same-block guard, cells of unloaded blocks added as load hints.
/// </summary>
public static class OutdoorParts
{
    /// <summary>Collects the land cells the parts' boxes cover.</summary>
    /// <param name="array">The array; a no-op while its latch is set, which this sets first (even for no parts).</param>
    /// <param name="parts">The parts; the first is the anchor (retail: first non-null part).</param>
    /// <param name="caller">The id of the cell whose find_transit_cells called this (the ACE guard's reference).</param>
    /// <param name="landscape">Which blocks are loaded.</param>
    /// <param name="fidelity">Retail by default; ACE's guard (§7 #3) and every-part-anchors (§7 #4) as options.</param>
    public static void AddAllOutsideCells(CellArray array, ReadOnlySpan<Part> parts, CellId caller, ILandscape landscape, PartsFidelity fidelity = default)
    {
        if (array.AddedOutside)
        {
            return;
        }

        array.AddedOutside = true;
        if (parts.IsEmpty)
        {
            return;
        }

        int minX = 0, minY = 0, maxX = 0, maxY = 0; // facts §3.4: the range always holds the anchor's own cell
        int anchors = fidelity.EveryPartAnchors ? parts.Length : 1;
        for (int a = 0; a < anchors; a++)
        {
            // ACE (§7 #4): every part anchors its own add_cell_block call, and the range is not reset between anchors.
            AddForAnchor(array, parts, parts[a], caller, landscape, fidelity, ref minX, ref minY, ref maxX, ref maxY);
        }
    }

    private static void AddForAnchor(CellArray array, ReadOnlySpan<Part> parts, Part anchorPart, CellId caller, ILandscape landscape, PartsFidelity fidelity, ref int minX, ref int minY, ref int maxX, ref int maxY)
    {
        var anchor = anchorPart.Cell;
        var origin = anchorPart.Frame.Origin;
        if (!LandDefs.AdjustToOutside(ref anchor, ref origin) || !LandDefs.GidToLcoord(anchor, out var g))
        {
            return; // retail: the anchor's land cell must resolve (ACE: this anchor is skipped)
        }

        int lx = (anchor.Low - 1) >> 3, ly = (anchor.Low - 1) & 7;
        foreach (var part in parts)
        {
            var (lo, hi) = Extent(part, anchor);
            if (!float.IsFinite(lo.X) || !float.IsFinite(lo.Y) || !float.IsFinite(hi.X) || !float.IsFinite(hi.Y))
            {
                continue; // a non-finite part names no cell (never a cell at index 0)
            }

            minX = Math.Min(minX, CellOf(lo.X) - lx);
            minY = Math.Min(minY, CellOf(lo.Y) - ly);
            maxX = Math.Max(maxX, CellOf(hi.X) - lx);
            maxY = Math.Max(maxY, CellOf(hi.Y) - ly);
        }

        AddCellBlock(array, g.X + minX, g.Y + minY, g.X + maxX, g.Y + maxY, caller, landscape, fidelity.SameBlockGuard);
    }

    /// <summary>Adds every on-map land cell of a global lcoord rectangle, x outer and y inner (<c>add_cell_block</c>, facts §3.4 step 4).</summary>
    /// <param name="array">The array.</param>
    /// <param name="minX">First column.</param>
    /// <param name="minY">First row.</param>
    /// <param name="maxX">Last column.</param>
    /// <param name="maxY">Last row.</param>
    /// <param name="caller">The calling cell (ACE guard reference).</param>
    /// <param name="landscape">Which blocks are loaded (unloaded cells are added as hints, in ACE too).</param>
    /// <param name="sameBlockGuard">ACE's guard.</param>
    public static void AddCellBlock(CellArray array, int minX, int minY, int maxX, int maxY, CellId caller, ILandscape landscape, bool sameBlockGuard = false)
    {
        for (int i = minX; i <= maxX; i++)
        {
            for (int j = minY; j <= maxY; j++)
            {
                if (!LandDefs.InBounds(i, j))
                {
                    continue;
                }

                var id = LandDefs.LcoordToGid(i, j);
                if (sameBlockGuard && (id.Value & LandDefs.BlockMask) != (caller.Value & LandDefs.BlockMask))
                {
                    continue;
                }

                array.Add(id, landscape.IsLoaded(id.Landblock));
            }
        }
    }

    /// <summary>
    /// Returns a part's extent in the anchor's re-seated block frame: Always2D parts the square ±r around the raw
    /// origin, others the axis-aligned hull of their box's 8 transformed corners (a full fold; ACE folds only 6).
    /// </summary>
    /// <param name="part">The part.</param>
    /// <param name="anchor">The anchor's re-seated land cell.</param>
    /// <returns>Minimum and maximum corner.</returns>
    public static (Vector2 Min, Vector2 Max) Extent(Part part, CellId anchor)
    {
        var shift = LandDefs.GetBlockOffset(part.Cell, anchor);
        if (part.Always2D)
        {
            var o = part.Frame.Origin - shift;
            return (new Vector2(o.X - part.Radius, o.Y - part.Radius), new Vector2(o.X + part.Radius, o.Y + part.Radius));
        }

        var min = new Vector2(float.PositiveInfinity);
        var max = new Vector2(float.NegativeInfinity);
        var b = part.Bounds;
        for (int k = 0; k < 8; k++)
        {
            var corner = new Vector3((k & 1) == 0 ? b.Min.X : b.Max.X, (k & 2) == 0 ? b.Min.Y : b.Max.Y, (k & 4) == 0 ? b.Min.Z : b.Max.Z);
            var p = part.Frame.LocalToGlobal(corner) - shift;
            min = Vector2.Min(min, new Vector2(p.X, p.Y));
            max = Vector2.Max(max, new Vector2(p.X, p.Y));
        }

        return (min, max);
    }

    private static int CellOf(float v) => (int)Math.Clamp(Math.Floor(v / (double)LandDefs.CellLength), -1_000_000, 1_000_000);
}
