using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Cli.Render;

/// <summary>The xy footprint of one env cell in world metres: one convex polygon per piece, and the cell's z range.</summary>
/// <param name="Id">The cell.</param>
/// <param name="Pieces">Per convex piece, its outline (counter-clockwise).</param>
/// <param name="ZMin">Lowest z of the cell's corners (block frame).</param>
/// <param name="ZMax">Highest z of the cell's corners (block frame).</param>
internal sealed record CellFootprint(CellId Id, IReadOnlyList<IReadOnlyList<WorldPoint>> Pieces, double ZMin, double ZMax)
{
    /// <summary>Gets the centroid of all piece corners.</summary>
    public WorldPoint Centre => new(Pieces.SelectMany(p => p).Average(p => p.X), Pieces.SelectMany(p => p).Average(p => p.Y));

    /// <summary>Gets the west, south, east and north limits.</summary>
    public (double MinX, double MinY, double MaxX, double MaxY) Bounds =>
        (Pieces.SelectMany(p => p).Min(p => p.X), Pieces.SelectMany(p => p).Min(p => p.Y), Pieces.SelectMany(p => p).Max(p => p.X), Pieces.SelectMany(p => p).Max(p => p.Y));
}

/// <summary>A portal of an env cell drawn on the map.</summary>
/// <param name="Owner">The cell the portal belongs to.</param>
/// <param name="Index">Its index in the owner's portal list.</param>
/// <param name="Portal">The portal.</param>
/// <param name="Points">Two points (a wall portal seen from above) or a polygon (a floor or ceiling portal), world metres.</param>
/// <param name="Inward">Unit xy direction from the portal into the owning cell (zero when the portal is horizontal).</param>
/// <param name="Approximate">True when the portal plane does not meet the cell's pieces, so a 1 m stub at the plane's nearest point is drawn instead.</param>
internal sealed record PortalTrace(CellId Owner, int Index, ScenePortal Portal, IReadOnlyList<WorldPoint> Points, WorldPoint Inward, bool Approximate);

/// <summary>
/// Projects scene geometry onto the world xy plane. A convex piece's corners are mapped through the cell frame
/// (origin + rotation, facts §5) into the block frame and then to world metres (192 m per block), and the footprint is the
/// convex hull of their xy projections: exact for boxes and for plane-list pieces alike (the projection of a convex
/// polytope is the hull of its projected vertices). A portal is the section of the cell's pieces by the portal plane
/// (corners on the plane, and every crossing of the plane by a segment between two corners), projected the same way.
/// Arithmetic is in double from the stored float values.
/// </summary>
internal static class SceneFootprint
{
    private const double OnPlane = 1e-3;

    /// <summary>Computes a cell's footprint.</summary>
    /// <param name="cell">The cell.</param>
    /// <returns>The footprint.</returns>
    public static CellFootprint Of(SceneCell cell)
    {
        var pieces = new List<IReadOnlyList<WorldPoint>>();
        double zMin = double.PositiveInfinity, zMax = double.NegativeInfinity;
        foreach (var piece in cell.Pieces)
        {
            var corners = piece.ToConvex().Vertices.Select(v => ToBlock(cell, v)).ToList();
            zMin = Math.Min(zMin, corners.Min(c => c.Z));
            zMax = Math.Max(zMax, corners.Max(c => c.Z));
            pieces.Add(Hull.Of(corners.Select(c => ToWorld(cell.Id, c))));
        }

        return new CellFootprint(cell.Id, pieces, zMin, zMax);
    }

    /// <summary>Computes where a portal of a cell lies on the map.</summary>
    /// <param name="cell">The owning cell.</param>
    /// <param name="index">The portal's index.</param>
    /// <returns>The trace.</returns>
    public static PortalTrace Portal(SceneCell cell, int index)
    {
        var portal = cell.Portals[index];
        var n = Vector3.Normalize(portal.Plane.Normal);
        double d = portal.Plane.D / portal.Plane.Normal.Length();
        var section = new List<(double X, double Y, double Z)>();
        var inside = new List<Vector3>();
        foreach (var piece in cell.Pieces)
        {
            var corners = piece.ToConvex().Vertices;
            inside.AddRange(corners);
            var dist = corners.Select(v => Vector3.Dot(n, v) + d).ToArray();
            for (int i = 0; i < corners.Count; i++)
            {
                if (Math.Abs(dist[i]) <= OnPlane)
                {
                    section.Add(ToBlock(cell, corners[i]));
                }

                for (int j = i + 1; j < corners.Count; j++)
                {
                    if ((dist[i] > OnPlane && dist[j] < -OnPlane) || (dist[i] < -OnPlane && dist[j] > OnPlane))
                    {
                        double t = dist[i] / (dist[i] - dist[j]);
                        section.Add(ToBlock(cell, corners[i] + ((float)t * (corners[j] - corners[i]))));
                    }
                }
            }
        }

        // Into the cell: from the plane toward the side the cell's corners lie on (the geometry, not PortalSide).
        var middle = inside.Aggregate(Vector3.Zero, (a, v) => a + v) / Math.Max(inside.Count, 1);
        float own = MathF.Sign(Vector3.Dot(n, middle) + (float)d);
        var inwardBlock = Rotate(cell.Rotation, (own == 0 ? 1 : own) * n);
        double len = Math.Sqrt((inwardBlock.X * inwardBlock.X) + (inwardBlock.Y * inwardBlock.Y));
        var inward = len < 1e-6 ? new WorldPoint(0, 0) : new WorldPoint(inwardBlock.X / len, inwardBlock.Y / len);

        bool approximate = section.Count == 0;
        if (approximate)
        {
            // The plane misses the pieces: a 1 m stub along the plane's trace at its point nearest the cell's middle.
            var foot = middle - ((Vector3.Dot(n, middle) + (float)d) * n);
            var along = Vector3.Cross(n, Vector3.UnitZ);
            along = along.LengthSquared() < 1e-6f ? Vector3.UnitX : Vector3.Normalize(along);
            section.Add(ToBlock(cell, foot - (0.5f * along)));
            section.Add(ToBlock(cell, foot + (0.5f * along)));
        }

        var points = Hull.Of(section.Select(p => ToWorld(cell.Id, p)));
        if (points.Count >= 3 && Hull.Area(points) < 1e-3)
        {
            points = Hull.Extremes(points);
        }

        return new PortalTrace(cell.Id, index, portal, points, inward, approximate);
    }

    /// <summary>Maps a point in a block frame to world metres.</summary>
    /// <param name="block">Any id in the block.</param>
    /// <param name="x">Block-frame x.</param>
    /// <param name="y">Block-frame y.</param>
    /// <returns>The world point.</returns>
    public static WorldPoint World(CellId block, double x, double y) => new((192.0 * block.BlockX) + x, (192.0 * block.BlockY) + y);

    private static WorldPoint ToWorld(CellId id, (double X, double Y, double Z) p) => World(id, p.X, p.Y);

    private static (double X, double Y, double Z) ToBlock(SceneCell cell, Vector3 local)
    {
        var r = Rotate(cell.Rotation, local);
        return (cell.Origin.X + r.X, cell.Origin.Y + r.Y, cell.Origin.Z + r.Z);
    }

    // q v q* in double: v + 2w(u × v) + 2u × (u × v), u the vector part.
    private static (double X, double Y, double Z) Rotate(Quaternion q, Vector3 v)
    {
        double qw = q.W, qx = q.X, qy = q.Y, qz = q.Z;
        double norm = Math.Sqrt((qw * qw) + (qx * qx) + (qy * qy) + (qz * qz));
        (qw, qx, qy, qz) = (qw / norm, qx / norm, qy / norm, qz / norm);
        double tx = 2 * ((qy * v.Z) - (qz * v.Y)), ty = 2 * ((qz * v.X) - (qx * v.Z)), tz = 2 * ((qx * v.Y) - (qy * v.X));
        return (v.X + (qw * tx) + ((qy * tz) - (qz * ty)), v.Y + (qw * ty) + ((qz * tx) - (qx * tz)), v.Z + (qw * tz) + ((qx * ty) - (qy * tx)));
    }
}
