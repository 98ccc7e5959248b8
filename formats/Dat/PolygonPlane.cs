using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>
/// The plane of a polygon from its vertices: the fan sum Σ (vᵢ − v₀) × (vᵢ₊₁ − v₀) (twice the area vector, Newell's
/// normal for a planar polygon), normalised, and d = −N·v₀. On an axis-aligned polygon every cross term has exact zeros
/// off the axis, so the plane comes back bit-exact.
/// </summary>
public static class PolygonPlane
{
    /// <summary>Computes the plane, or null when the vertices span no area.</summary>
    /// <param name="vertices">At least three vertices in winding order (the normal follows the right-hand rule).</param>
    /// <returns>The unit-normal plane, or null.</returns>
    public static CellPlane? Of(IReadOnlyList<Vector3> vertices)
    {
        if (vertices.Count < 3)
        {
            return null;
        }

        var sum = Vector3.Zero;
        for (int i = 1; i + 1 < vertices.Count; i++)
        {
            sum += Vector3.Cross(vertices[i] - vertices[0], vertices[i + 1] - vertices[0]);
        }

        float length = sum.Length();
        if (!(length > 1e-12f) || !float.IsFinite(length))
        {
            return null;
        }

        var n = sum / length;
        return new CellPlane(n, -Vector3.Dot(n, vertices[0]));
    }

    /// <summary>Returns the unit-normal form of a plane, as <see cref="AcPhys.Contract.SceneBuild"/> gives it to the core.</summary>
    /// <param name="p">A plane with a non-zero normal.</param>
    /// <returns>N/|N|, D/|N|.</returns>
    public static CellPlane Unit(CellPlane p) => new(Vector3.Normalize(p.Normal), p.D / p.Normal.Length());

    /// <summary>Returns two in-plane axes u, v with u × v = n; exact unit axes when n is an axis direction.</summary>
    /// <param name="n">A unit normal.</param>
    /// <returns>The axes.</returns>
    public static (Vector3 U, Vector3 V) Tangents(Vector3 n)
    {
        if (AxisOf(n) is { } axis)
        {
            var (u, v) = axis switch
            {
                0 => (Vector3.UnitY, Vector3.UnitZ),
                1 => (Vector3.UnitZ, Vector3.UnitX),
                _ => (Vector3.UnitX, Vector3.UnitY),
            };
            return n[axis] > 0 ? (u, v) : (v, u);
        }

        var a = Vector3.Abs(n);
        var t = a.X <= a.Y && a.X <= a.Z ? Vector3.UnitX : a.Y <= a.Z ? Vector3.UnitY : Vector3.UnitZ;
        var uu = Vector3.Normalize(Vector3.Cross(n, t));
        return (uu, Vector3.Cross(n, uu));
    }

    /// <summary>Returns the axis (0, 1, 2) a normal lies along exactly, or null.</summary>
    /// <param name="n">A normal.</param>
    /// <returns>The axis, or null.</returns>
    public static int? AxisOf(Vector3 n) =>
        n.Y == 0 && n.Z == 0 && n.X != 0 ? 0 : n.X == 0 && n.Z == 0 && n.Y != 0 ? 1 : n.X == 0 && n.Y == 0 && n.Z != 0 ? 2 : null;
}
