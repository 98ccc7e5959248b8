using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// A convex piece of a cell's volume: the intersection of the inner half-spaces of its planes (N·p + D ≥ 0 is
/// inside), in the cell's local frame. Cells are unions of pieces (an L-shaped room is two boxes).
/// </summary>
public sealed class ConvexPiece
{
    private readonly CellPlane[] planes;

    /// <summary>Initializes a new instance.</summary>
    /// <param name="planes">Inner half-spaces; at least 4, each valid, and bounded (a finite, non-empty volume).</param>
    /// <exception cref="ArgumentException">A plane is degenerate or non-finite, or the planes bound no finite volume.</exception>
    public ConvexPiece(IReadOnlyList<CellPlane> planes)
    {
        if (planes.Count < 4)
        {
            throw new ArgumentException("a convex piece needs at least 4 planes", nameof(planes));
        }

        this.planes = new CellPlane[planes.Count];
        for (int i = 0; i < planes.Count; i++)
        {
            if (!planes[i].IsValid)
            {
                throw new ArgumentException($"plane {i} is degenerate or non-finite", nameof(planes));
            }

            this.planes[i] = new CellPlane(Vector3.Normalize(planes[i].Normal), planes[i].D / planes[i].Normal.Length());
        }

        Vertices = ComputeVertices(this.planes);
        if (Vertices.Count < 4 || Unbounded(this.planes))
        {
            throw new ArgumentException("the planes bound no finite volume", nameof(planes));
        }

        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        foreach (var v in Vertices)
        {
            min = Vector3.Min(min, v);
            max = Vector3.Max(max, v);
        }

        Bounds = new Box(min, max);
    }

    /// <summary>Gets the planes (unit normals pointing inward).</summary>
    public IReadOnlyList<CellPlane> Planes => planes;

    /// <summary>Gets the corner vertices.</summary>
    /// <remarks>
    /// Each is the meeting point of three planes whose normals' determinant has |det| ≥ 1e-6 (smaller is parallel),
    /// kept when it is at most 1e-3 behind every plane (N·v + D ≥ −1e-3, inclusive), and dropped as a repeat when it
    /// is closer than 1e-4 to an earlier corner (squared distance &lt; 1e-8; exactly 1e-8 is a new corner).
    /// </remarks>
    public IReadOnlyList<Vector3> Vertices { get; }

    /// <summary>Gets the axis-aligned bounds of the vertices.</summary>
    public Box Bounds { get; }

    /// <summary>Returns the box around a cell's pieces: the per-axis min and max of their bounds.</summary>
    /// <param name="pieces">At least one piece.</param>
    /// <returns>The box.</returns>
    public static Box BoundsOf(IReadOnlyList<ConvexPiece> pieces)
    {
        if (pieces.Count == 0)
        {
            throw new ArgumentException("a cell needs at least one piece", nameof(pieces));
        }

        var min = pieces[0].Bounds.Min;
        var max = pieces[0].Bounds.Max;
        foreach (var p in pieces)
        {
            min = Vector3.Min(min, p.Bounds.Min);
            max = Vector3.Max(max, p.Bounds.Max);
        }

        return new Box(min, max);
    }

    /// <summary>Returns the axis-aligned box min..max as a piece.</summary>
    /// <param name="min">Minimum corner.</param>
    /// <param name="max">Maximum corner (each coordinate &gt; min's).</param>
    /// <returns>The piece.</returns>
    public static ConvexPiece FromBox(Vector3 min, Vector3 max) => new(
    [
        new CellPlane(Vector3.UnitX, -min.X), new CellPlane(-Vector3.UnitX, max.X),
        new CellPlane(Vector3.UnitY, -min.Y), new CellPlane(-Vector3.UnitY, max.Y),
        new CellPlane(Vector3.UnitZ, -min.Z), new CellPlane(-Vector3.UnitZ, max.Z),
    ]);

    /// <summary>Tests exact containment (closed, no EPS): every plane distance ≥ 0.</summary>
    /// <param name="p">A local point.</param>
    /// <returns>True when inside or on the boundary.</returns>
    public bool Contains(Vector3 p)
    {
        foreach (var plane in planes)
        {
            if (plane.Distance(p) < 0)
            {
                return false;
            }
        }

        return true;
    }

    // Loops, not LINQ: a closure per corner candidate was most of a scene read's time (issue 26); the same tests in the same order.
    private static List<Vector3> ComputeVertices(CellPlane[] planes)
    {
        var result = new List<Vector3>();
        for (int i = 0; i < planes.Length; i++)
        {
            for (int j = i + 1; j < planes.Length; j++)
            {
                for (int k = j + 1; k < planes.Length; k++)
                {
                    if (!Intersect(planes[i], planes[j], planes[k], out var v) || !InsideAll(planes, v) || Repeats(result, v))
                    {
                        continue;
                    }

                    result.Add(v);
                }
            }
        }

        return result;
    }

    // N·v + D ≥ −1e-3 for every plane (a NaN distance fails).
    private static bool InsideAll(CellPlane[] planes, Vector3 v)
    {
        foreach (var p in planes)
        {
            if (!(p.Distance(v) >= -1e-3f))
            {
                return false;
            }
        }

        return true;
    }

    private static bool Repeats(List<Vector3> corners, Vector3 v)
    {
        foreach (var r in corners)
        {
            if (Vector3.DistanceSquared(r, v) < 1e-8f)
            {
                return true;
            }
        }

        return false;
    }

    // Bounded iff no direction v has N·v ≥ 0 for every plane; the extreme rays of that cone are ±Nᵢ×Nⱼ or ±Nᵢ.
    private static bool Unbounded(CellPlane[] planes)
    {
        for (int i = 0; i < planes.Length; i++)
        {
            if (Recedes(planes, planes[i].Normal) || Recedes(planes, -planes[i].Normal))
            {
                return true;
            }

            for (int j = i + 1; j < planes.Length; j++)
            {
                var v = Vector3.Cross(planes[i].Normal, planes[j].Normal);
                if (Recedes(planes, v) || Recedes(planes, -v))
                {
                    return true;
                }
            }
        }

        return false;
    }

    // Whether the volume goes on for ever along v: v is not null and N·v̂ ≥ −1e-6 for every plane (a NaN fails).
    private static bool Recedes(CellPlane[] planes, Vector3 v)
    {
        if (!(v.LengthSquared() > 1e-10f))
        {
            return false;
        }

        var unit = Vector3.Normalize(v);
        foreach (var p in planes)
        {
            if (!(Vector3.Dot(p.Normal, unit) >= -1e-6f))
            {
                return false;
            }
        }

        return true;
    }

    private static bool Intersect(CellPlane a, CellPlane b, CellPlane c, out Vector3 v)
    {
        var bc = Vector3.Cross(b.Normal, c.Normal);
        float det = Vector3.Dot(a.Normal, bc);
        if (MathF.Abs(det) < 1e-6f)
        {
            v = default;
            return false;
        }

        v = ((-a.D * bc) - (b.D * Vector3.Cross(c.Normal, a.Normal)) - (c.D * Vector3.Cross(a.Normal, b.Normal))) / det;
        return float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z);
    }
}
