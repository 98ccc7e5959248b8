using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Where a part's frame is held: the anchor's cell and block frame, or — for some parts of a body near a block line —
/// a land cell of the neighbouring block, its origin re-based by ±192 m so its world position is unchanged (facts
/// §3.4, §5.2, §5.8: every part has its own cell, and GetBlockOffset takes its box into each cell's frame).
/// </summary>
internal static class PartFrames
{
    /// <summary>How near a block line (metres, in the frame's block) a part's centre must be to be framed across it.</summary>
    public const float NearLine = 24f;

    /// <summary>Returns whether part <paramref name="k"/> at a step is framed across a block line when near one: every other non-anchor part.</summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index (the anchor, 0, never).</param>
    /// <returns>True to frame it across.</returns>
    public static bool Across(int step, int k) => k > 0 && ((step + k) & 1) == 1;

    /// <summary>
    /// Re-frames a point held in <paramref name="cell"/>'s block into the neighbouring block across the nearest block line
    /// when it lies within <see cref="NearLine"/> of it and that block is on the map: the land cell of that block nearest
    /// the point, and the point minus 192·(Δbx, Δby).
    /// </summary>
    /// <param name="cell">The cell whose block frame <paramref name="origin"/> is in.</param>
    /// <param name="origin">The point.</param>
    /// <returns>The neighbouring block's land cell and the re-based point, or null when not near a line on the map.</returns>
    public static (CellId Cell, Vector3 Origin)? AcrossLine(CellId cell, Vector3 origin)
    {
        float toWest = origin.X, toEast = LandDefs.BlockLength - origin.X, toSouth = origin.Y, toNorth = LandDefs.BlockLength - origin.Y;
        float nearest = MathF.Min(MathF.Min(toWest, toEast), MathF.Min(toSouth, toNorth));
        if (!(nearest >= -NearLine && nearest < NearLine))
        {
            return null; // far from every line (or a point outside its block: not re-framed)
        }

        int dx = 0, dy = 0;
        if (nearest == toWest)
        {
            dx = -1;
        }
        else if (nearest == toEast)
        {
            dx = 1;
        }
        else if (nearest == toSouth)
        {
            dy = -1;
        }
        else
        {
            dy = 1;
        }

        int bx = cell.BlockX + dx, by = cell.BlockY + dy;
        if (bx < 0 || by < 0 || bx > 0xFE || by > 0xFE)
        {
            return null; // the map's edge: no neighbouring block
        }

        var rebased = origin - new Vector3(LandDefs.BlockLength * dx, LandDefs.BlockLength * dy, 0);
        int lx = Math.Clamp((int)MathF.Floor(rebased.X / LandDefs.CellLength), 0, 7), ly = Math.Clamp((int)MathF.Floor(rebased.Y / LandDefs.CellLength), 0, 7);
        return (new CellId(((uint)bx << 24) | ((uint)by << 16) | (uint)(1 + (8 * lx) + ly)), rebased);
    }
}
