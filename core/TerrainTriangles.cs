using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// Retail's land-cell <c>point_in_cell</c> (facts §5.5, §5.6): float32 <c>point_in_poly2D</c> over the cell's two terrain
/// triangles, the diagonal chosen by the cell's global lcoord. The union is the closed 24 m square up to rounding: the
/// subtraction <c>p − vertex</c> in float32 lets a triangle accept points up to half an ulp of the cell's coordinates
/// outside the square next to a corner the triangle's edges do not bound (docs/conformance.md, "Land-cell edges").
/// </summary>
public static class TerrainTriangles
{
    /// <summary>
    /// Tests whether a cell's diagonal runs SW–NE (facts §5.6): <c>s = gy·(214614067·gx + 1813693831) − 1109124029·gx −
    /// 1369149221</c> in unsigned 32-bit wrap-around arithmetic, and <c>s·2.3283064e−10 ≥ 0.5</c>. The multiplier is not
    /// exactly 2⁻³², but no cell of the 2040² map has s in the window it moves, so <c>s ≥ 2³¹</c> is the same rule.
    /// </summary>
    /// <param name="gx">The cell's global column.</param>
    /// <param name="gy">The cell's global row.</param>
    /// <returns>True for the SW–NE cut.</returns>
    public static bool CutsSouthWestToNorthEast(int gx, int gy)
    {
        uint x = unchecked((uint)gx), y = unchecked((uint)gy);
        uint s = unchecked((y * ((214614067u * x) + 1813693831u)) - (1109124029u * x) - 1369149221u);
        return s >= 0x8000_0000u;
    }

    /// <summary>
    /// Tests a block-frame point against a land cell as retail does: inside or on either terrain triangle, z ignored.
    /// A non-finite coordinate is outside (the reference's hardening: retail's crosses would be NaN and reject nothing,
    /// facts §6.17).
    /// </summary>
    /// <param name="cell">A land cell id.</param>
    /// <param name="p">A point in the cell's block frame.</param>
    /// <returns>True when a triangle contains the point.</returns>
    public static bool Contains(CellId cell, Vector3 p)
    {
        if (!float.IsFinite(p.X) || !float.IsFinite(p.Y))
        {
            return false;
        }

        int idx = cell.Low - 1, cx = idx >> 3, cy = idx & 7;
        float west = LandDefs.CellLength * cx, south = LandDefs.CellLength * cy;
        float east = west + LandDefs.CellLength, north = south + LandDefs.CellLength;
        var sw = new Vector2(west, south);
        var se = new Vector2(east, south);
        var nw = new Vector2(west, north);
        var ne = new Vector2(east, north);
        var q = new Vector2(p.X, p.Y);

        // Polygon 0 is tested first (find_terrain_poly); for membership only the union matters.
        return CutsSouthWestToNorthEast((cell.BlockX * 8) + cx, (cell.BlockY * 8) + cy)
            ? InTriangle(sw, se, ne, q) || InTriangle(sw, ne, nw, q)
            : InTriangle(sw, se, nw, q) || InTriangle(ne, nw, se, q);
    }

    // point_in_poly2D, side Positive (facts §5.5): edges v0→v2, v2→v1, v1→v0; for edge prev→cur the float32 cross
    // (cur − prev) × (p − cur) rejects when > 0. Each product and difference is rounded to float32, as retail's.
    private static bool InTriangle(Vector2 v0, Vector2 v1, Vector2 v2, Vector2 p) =>
        !Rejects(v0, v2, p) && !Rejects(v2, v1, p) && !Rejects(v1, v0, p);

    private static bool Rejects(Vector2 prev, Vector2 cur, Vector2 p)
    {
        float ax = cur.X - prev.X, ay = cur.Y - prev.Y;
        float bx = p.X - cur.X, by = p.Y - cur.Y;
        float xy = ax * by, yx = ay * bx;
        return xy - yx > 0f;
    }
}
