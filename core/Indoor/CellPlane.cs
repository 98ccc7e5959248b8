using System.Numerics;

namespace AcPhys.Core;

/// <summary>Which side of a plane a point is on, with the EPS band (facts §5.7, PE:20-29).</summary>
public enum Side
{
    /// <summary>d &gt; EPS.</summary>
    Front,

    /// <summary>d &lt; −EPS.</summary>
    Behind,

    /// <summary>|d| ≤ EPS.</summary>
    Close,
}

/// <summary>A plane N·p + D = 0 in some cell-local frame; the positive half-space is N·p + D &gt; 0.</summary>
/// <param name="Normal">The normal (unit length for planes built by this library).</param>
/// <param name="D">The offset.</param>
/// <threadsafety>Immutable value type.</threadsafety>
public readonly record struct CellPlane(Vector3 Normal, float D)
{
    /// <summary>Gets a value indicating whether the plane is usable: finite and with a non-zero normal.</summary>
    public bool IsValid => float.IsFinite(Normal.X) && float.IsFinite(Normal.Y) && float.IsFinite(Normal.Z) && float.IsFinite(D) && Normal.LengthSquared() > 1e-12f;

    /// <summary>Returns the plane through a point with a normal.</summary>
    /// <param name="normal">The normal (normalised here).</param>
    /// <param name="point">A point on the plane.</param>
    /// <returns>The plane.</returns>
    public static CellPlane Through(Vector3 normal, Vector3 point)
    {
        var n = Vector3.Normalize(normal);
        return new CellPlane(n, -Vector3.Dot(n, point));
    }

    /// <summary>Returns the signed distance N·p + D.</summary>
    /// <param name="p">A point.</param>
    /// <returns>The distance (metres when N is a unit vector).</returns>
    public float Distance(Vector3 p) => Vector3.Dot(Normal, p) + D;

    /// <summary>Classifies a point with the EPS band and an optional bias added to the distance (PE:20-29).</summary>
    /// <param name="p">A point.</param>
    /// <param name="bias">Added to the distance before classifying.</param>
    /// <returns>The side.</returns>
    public Side Classify(Vector3 p, float bias = 0f)
    {
        float d = Distance(p) + bias;
        return d > LandDefs.Epsilon ? Side.Front : d < -LandDefs.Epsilon ? Side.Behind : Side.Close;
    }
}
