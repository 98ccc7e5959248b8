using System.Numerics;
using AcPhys.Contract;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// One env cell of a scene in double precision, read from the scene description alone (not from the core's BSP):
/// the frame, the first piece's inner planes normalised, and each portal's plane normalised, all in the cell's local
/// frame. Only the first piece: retail's three cell queries follow the BSP's positive chain, which holds piece 0, and
/// never the negative children where further pieces hang (facts §5.7) — a port that walks them (the union) deviates.
/// </summary>
/// <remarks>
/// Depths are plane-wise (the minimum over a piece's planes of the signed distance), which is what the BSP queries
/// answer (facts §5.7: every plane on the positive chain; the sphere test is "no plane has d ≤ −R"), not the exact
/// Euclidean distance to a polyhedron.
/// </remarks>
internal sealed class ExactCell
{
    private readonly double[] first; // (nx, ny, nz, d) × planes of piece 0
    private readonly double[] portals; // per portal: (nx, ny, nz, d)
    private readonly double ox, oy, oz, qx, qy, qz, qw;

    /// <summary>Initializes a new instance.</summary>
    /// <param name="source">The cell description.</param>
    public ExactCell(SceneCell source)
    {
        Source = source;
        (ox, oy, oz) = (source.Origin.X, source.Origin.Y, source.Origin.Z);
        var q = source.Rotation;
        double n = Math.Sqrt(((double)q.X * q.X) + ((double)q.Y * q.Y) + ((double)q.Z * q.Z) + ((double)q.W * q.W));
        (qx, qy, qz, qw) = (q.X / n, q.Y / n, q.Z / n, q.W / n);
        first = PlanesOf(source.Pieces[0]);
        portals = [.. source.Portals.SelectMany(p => Normalised(p.Plane.Normal, p.Plane.D))];
    }

    /// <summary>Gets the description.</summary>
    public SceneCell Source { get; }

    /// <summary>Gets a value indicating whether the cell has portals (retail's point_in_cell is false without, facts §5.5).</summary>
    public bool HasPortals => Source.Portals.Count > 0;

    /// <summary>Returns the plane-wise depth of a point in the first piece, the one on the BSP's positive chain (facts §5.7; docs/indoor.md "Unions").</summary>
    /// <param name="p">A point in the cell's block frame.</param>
    /// <returns>Metres: &gt; 0 inside every plane.</returns>
    public double DepthFirst(Vector3 p) => Depth(first, Local(p));

    /// <summary>Returns the signed distance of a point from portal <paramref name="index"/>'s plane (normalised), in the cell's frame.</summary>
    /// <param name="index">Portal index.</param>
    /// <param name="p">A point in the cell's block frame.</param>
    /// <returns>Metres.</returns>
    public double PortalDistance(int index, Vector3 p)
    {
        var (x, y, z) = Local(p);
        int k = 4 * index;
        return (portals[k] * x) + (portals[k + 1] * y) + (portals[k + 2] * z) + portals[k + 3];
    }

    private static double Depth(double[] planes, (double X, double Y, double Z) l)
    {
        double worst = double.PositiveInfinity;
        for (int k = 0; k < planes.Length; k += 4)
        {
            worst = Math.Min(worst, (planes[k] * l.X) + (planes[k + 1] * l.Y) + (planes[k + 2] * l.Z) + planes[k + 3]);
        }

        return worst;
    }

    private static double[] PlanesOf(ScenePiece piece)
    {
        if (piece.Box is { } b)
        {
            // x ≥ min.x, x ≤ max.x, … as inner half-spaces.
            return [1, 0, 0, -b.Min.X, -1, 0, 0, b.Max.X, 0, 1, 0, -b.Min.Y, 0, -1, 0, b.Max.Y, 0, 0, 1, -b.Min.Z, 0, 0, -1, b.Max.Z];
        }

        return [.. piece.Planes!.SelectMany(p => Normalised(p.Normal, p.D))];
    }

    private static double[] Normalised(Vector3 normal, float d)
    {
        double len = Math.Sqrt(((double)normal.X * normal.X) + ((double)normal.Y * normal.Y) + ((double)normal.Z * normal.Z));
        return [normal.X / len, normal.Y / len, normal.Z / len, d / len];
    }

    // Rᵀ·(p − origin) (facts §5.8), the inverse rotation as the conjugate quaternion: v + w·t + u × t, t = 2·(u × v).
    private (double X, double Y, double Z) Local(Vector3 p)
    {
        double vx = p.X - ox, vy = p.Y - oy, vz = p.Z - oz;
        double ux = -qx, uy = -qy, uz = -qz;
        double tx = 2 * ((uy * vz) - (uz * vy)), ty = 2 * ((uz * vx) - (ux * vz)), tz = 2 * ((ux * vy) - (uy * vx));
        return (vx + (qw * tx) + ((uy * tz) - (uz * ty)), vy + (qw * ty) + ((uz * tx) - (ux * tz)), vz + (qw * tz) + ((ux * ty) - (uy * tx)));
    }
}
