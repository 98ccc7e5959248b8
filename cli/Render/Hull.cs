namespace AcPhys.Cli.Render;

/// <summary>The convex hull of points in the plane (Andrew's monotone chain), counter-clockwise, without repeats or collinear points.</summary>
internal static class Hull
{
    /// <summary>Points closer than this (metres) count as one.</summary>
    public const double Tolerance = 1e-5;

    /// <summary>Computes the hull.</summary>
    /// <param name="points">The points.</param>
    /// <returns>The hull's corners, counter-clockwise from the lowest-x point; one or two points when the input is degenerate.</returns>
    public static IReadOnlyList<WorldPoint> Of(IEnumerable<WorldPoint> points)
    {
        var sorted = points.OrderBy(p => p.X).ThenBy(p => p.Y).ToList();
        var unique = new List<WorldPoint>();
        foreach (var p in sorted)
        {
            if (!unique.Any(q => q.DistanceTo(p) < Tolerance))
            {
                unique.Add(p);
            }
        }

        if (unique.Count < 3)
        {
            return unique;
        }

        var hull = new List<WorldPoint>();
        foreach (var pass in new[] { unique, Enumerable.Reverse(unique).ToList() })
        {
            int start = hull.Count;
            foreach (var p in pass)
            {
                while (hull.Count >= start + 2 && Cross(hull[^2], hull[^1], p) <= 1e-9 * hull[^2].DistanceTo(hull[^1]) * hull[^2].DistanceTo(p))
                {
                    hull.RemoveAt(hull.Count - 1);
                }

                hull.Add(p);
            }

            hull.RemoveAt(hull.Count - 1);
        }

        return hull.Count >= 3 ? hull : Extremes(unique);
    }

    /// <summary>Returns the two points farthest apart.</summary>
    /// <param name="points">At least one point.</param>
    /// <returns>Two points (or the single one).</returns>
    public static IReadOnlyList<WorldPoint> Extremes(IReadOnlyList<WorldPoint> points)
    {
        if (points.Count < 2)
        {
            return points;
        }

        var best = (A: points[0], B: points[1]);
        foreach (var a in points)
        {
            foreach (var b in points)
            {
                if (a.DistanceTo(b) > best.A.DistanceTo(best.B))
                {
                    best = (a, b);
                }
            }
        }

        return [best.A, best.B];
    }

    /// <summary>Gets the area of a polygon (shoelace, absolute).</summary>
    /// <param name="polygon">The corners in order.</param>
    /// <returns>Square metres.</returns>
    public static double Area(IReadOnlyList<WorldPoint> polygon)
    {
        double sum = 0;
        for (int i = 0; i < polygon.Count; i++)
        {
            var (a, b) = (polygon[i], polygon[(i + 1) % polygon.Count]);
            sum += (a.X * b.Y) - (b.X * a.Y);
        }

        return Math.Abs(sum) / 2;
    }

    private static double Cross(WorldPoint o, WorldPoint a, WorldPoint b) => ((a.X - o.X) * (b.Y - o.Y)) - ((a.Y - o.Y) * (b.X - o.X));
}
