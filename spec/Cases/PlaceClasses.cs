using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>Boundary classes of outdoor queries and walks (where the spheres sit relative to cell and block lines, map edges, radii).</summary>
public static class PlaceClasses
{
    /// <summary>Returns the classes of a query, most boundary-like first.</summary>
    /// <param name="c">The query.</param>
    /// <returns>Tags.</returns>
    public static IEnumerable<string> OfQuery(OutdoorCase c)
    {
        var tags = new List<string>();
        if (c.Spheres.Any(s => !float.IsFinite(s.Center.X) || !float.IsFinite(s.Center.Y)))
        {
            tags.Add("centre:nonfinite");
        }
        else if (c.Spheres.Any(s => Math.Abs(s.Center.X) >= 1e6 || Math.Abs(s.Center.Y) >= 1e6))
        {
            tags.Add("centre:huge");
        }
        else if (c.Spheres.Any(s => float.IsSubnormal(s.Center.X) || float.IsSubnormal(s.Center.Y)))
        {
            tags.Add("centre:subnormal");
        }

        if (Position(c.Cell) is string position)
        {
            tags.Add(position);
        }

        if (c.Spheres.Count == 0)
        {
            tags.Add("query:no-spheres");
        }

        if (c.Spheres.Any(Touches))
        {
            tags.Add("radius:touches-edge");
        }

        if (c.Spheres.Count > 0)
        {
            var s = c.Spheres[0];
            tags.Add("centre:" + Place(s.Center.X, s.Center.Y, s.Radius));
            if (NearCorner(s.Center.X, s.Center.Y))
            {
                tags.Add("centre:within-1um-of-a-corner");
            }

            tags.Add(s.Radius == 0 ? "radius:0" : s.Radius >= 24 ? "radius:>=24" : s.Radius > 12 ? "radius:>12" : "radius:<=12");
        }

        if (c.Spheres.Count > 1)
        {
            tags.Add("spheres:multi");
        }

        if (c.Cell.BlockX is 0 or 0xFE || c.Cell.BlockY is 0 or 0xFE)
        {
            tags.Add("block:map-edge");
        }

        return tags;
    }

    /// <summary>Returns the classes of a walk, from sphere 0's world path (no implementation involved).</summary>
    /// <param name="w">The walk.</param>
    /// <returns>Tags.</returns>
    public static IEnumerable<string> OfWalk(Walk w)
    {
        var tags = new SortedSet<string>(StringComparer.Ordinal);
        var o = w.Body.Count > 0 ? w.Body[0].Offset : default;
        double x = (192.0 * w.StartCell.BlockX) + w.Start.X + o.X, y = (192.0 * w.StartCell.BlockY) + w.Start.Y + o.Y;
        AddPoint(tags, x, y);
        foreach (var step in w.Steps)
        {
            double nx = x + step.X, ny = y + step.Y;
            if (Math.Floor(nx / 192) != Math.Floor(x / 192) || Math.Floor(ny / 192) != Math.Floor(y / 192))
            {
                tags.Add("walk:crosses-block");
            }
            else if (Math.Floor(nx / 24) != Math.Floor(x / 24) || Math.Floor(ny / 24) != Math.Floor(y / 24))
            {
                tags.Add("walk:crosses-cell");
            }

            double len = Math.Sqrt((step.X * step.X) + (step.Y * step.Y));
            if (len > 192)
            {
                tags.Add("walk:jump");
            }
            else if (len > 0 && len < 1e-4)
            {
                tags.Add("walk:ulp-step");
            }

            (x, y) = (nx, ny);
            AddPoint(tags, x, y);
        }

        if (w.Body.Count > 1)
        {
            tags.Add("walk:multi-sphere");
        }

        if (w.Body.Any(b => b.Radius > 12))
        {
            tags.Add("walk:radius>12");
        }

        return tags;
    }

    // The kind of position, when not a land cell (facts §1.1, §6.12).
    private static string? Position(CellId cell) =>
        cell.IsNone ? "position:id-0"
        : !LandDefs.CellInRange(cell.Low) ? "position:malformed"
        : cell.BlockX == 0xFF || cell.BlockY == 0xFF ? "position:block-FF"
        : cell.Low == 0xFFFF ? "position:block-id"
        : cell.Low >= LandDefs.FirstEnvCellId ? "position:env"
        : null;

    // A disc whose radius is exactly the distance from its centre to a line of its cell (facts §6.7).
    private static bool Touches(Sphere s)
    {
        if (s.Radius <= 0 || !float.IsFinite(s.Center.X) || !float.IsFinite(s.Center.Y))
        {
            return false;
        }

        double px = s.Center.X - (24.0 * Math.Floor(s.Center.X / 24.0)), py = s.Center.Y - (24.0 * Math.Floor(s.Center.Y / 24.0));
        return px == s.Radius || 24 - px == s.Radius || py == s.Radius || 24 - py == s.Radius;
    }

    private static void AddPoint(SortedSet<string> tags, double x, double y)
    {
        double map = 192.0 * 255;
        if (x < 0 || y < 0 || x >= map || y >= map)
        {
            tags.Add("walk:off-map");
        }
        else if (x < 192 || y < 192 || x >= map - 192 || y >= map - 192)
        {
            tags.Add("walk:map-edge-block");
        }

        if (x % 24 == 0 || y % 24 == 0)
        {
            tags.Add("walk:on-line");
        }

        if (Dist(x, 192) < 1 && Dist(y, 192) < 1)
        {
            tags.Add("walk:block-corner");
        }
    }

    private static string Place(float x, float y, float r)
    {
        if (x < 0 || y < 0 || x >= LandDefs.BlockLength || y >= LandDefs.BlockLength)
        {
            return "outside-frame";
        }

        double bx = Dist(x, 192), by = Dist(y, 192), cx = Dist(x, 24), cy = Dist(y, 24);
        if (bx == 0 || by == 0)
        {
            return "on-block-line";
        }

        if (cx == 0 || cy == 0)
        {
            return "on-cell-line";
        }

        if (bx < r && by < r)
        {
            return "block-corner";
        }

        if (bx < r || by < r)
        {
            return "near-block-line";
        }

        return cx < r || cy < r ? "near-cell-line" : "interior";
    }

    // Within a micrometre of a cell corner but not on it: where retail's float32 triangles and the closed square differ (facts §5.5).
    private static bool NearCorner(float x, float y)
    {
        double cx = Dist(x, 24), cy = Dist(y, 24);
        return cx < 1e-6 && cy < 1e-6 && (cx != 0 || cy != 0);
    }

    private static double Dist(double v, double period) => Math.Abs(v - (period * Math.Round(v / period)));
}
