using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The shape of the part a body sphere stands for at a step of a scene walk: its rotation and its local box, chosen
/// from the step index and the sphere's index alone (no randomness: the shrinker's smaller walk has the same parts at
/// the steps it keeps). The shapes tell a port's frame and box bugs apart: boxes with a different extent per axis and
/// offset from the part's origin, yawed on every step and pitched and rolled too on odd steps.
/// </summary>
/// <remarks>
/// Every corner of a local box lies within <see cref="Reach"/>·r of the part's origin (|offset| + |half extents|,
/// permuted together: (0.10, 0.06, 0.04) + (0.28, 0.18, 0.12), length 0.477). Whatever the rotation and the target
/// cell's frame, the box's axis-aligned hull there then lies within √3·0.48·r ≈ 0.83·r of the origin on every axis
/// direction, so a hull that crosses a portal's plane has its part's centre within 0.83·r &lt; r of the plane: the
/// part's sphere gate (facts §5.2, §5.3: R = r + EPS) passes. The oracles still test the sphere gate themselves.
/// </remarks>
internal static class PartShapes
{
    /// <summary>A bound on |corner| / r of every local box (see remarks).</summary>
    public const float Reach = 0.48f;

    private static readonly Vector3 Half = new(0.28f, 0.18f, 0.12f);
    private static readonly Vector3 Offset = new(0.10f, 0.06f, 0.04f);

    /// <summary>Returns whether a step's parts are pitched and rolled as well as yawed.</summary>
    /// <param name="step">The step index.</param>
    /// <returns>True on odd steps.</returns>
    public static bool Tilted(int step) => (step & 1) == 1;

    /// <summary>Returns the rotation of part <paramref name="k"/> at a step: a yaw of 37°·step + 53°·k, and on odd steps a pitch and a roll of 14° to 40° with alternating signs.</summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index (0 = the anchor).</param>
    /// <returns>A unit quaternion.</returns>
    public static Quaternion Rotation(int step, int k)
    {
        var yaw = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Degrees(((step * 37) + (k * 53)) % 360));
        if (!Tilted(step))
        {
            return yaw;
        }

        float pitch = (14 + ((step * 7) + (k * 11)) % 27) * (((step >> 1) & 1) == 0 ? 1 : -1);
        float roll = (14 + ((step * 13) + (k * 5)) % 27) * (((step + k) & 1) == 0 ? 1 : -1);
        var q = yaw * Quaternion.CreateFromAxisAngle(Vector3.UnitY, Degrees(pitch)) * Quaternion.CreateFromAxisAngle(Vector3.UnitX, Degrees(roll));
        return Quaternion.Normalize(q);
    }

    /// <summary>Returns the local box of part <paramref name="k"/> at a step: half extents (0.28, 0.18, 0.12)·r and an offset of (±0.10, ±0.06, ±0.04)·r, both permuted over the axes by (step + k) mod 3, the offset's signs by step and part.</summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index.</param>
    /// <param name="radius">The sphere's radius.</param>
    /// <returns>The box (never centred on the origin).</returns>
    public static Box Bounds(int step, int k, float radius)
    {
        int turn = (step + k) % 3;
        var half = Permute(Half, turn) * radius;
        int signs = (step * 3) + k;
        var offset = Permute(Offset, turn) * radius * new Vector3((signs & 1) == 0 ? 1 : -1, (signs & 2) == 0 ? 1 : -1, (signs & 4) == 0 ? 1 : -1);
        return new Box(offset - half, offset + half);
    }

    /// <summary>Returns a box of the same size centred on the part's origin (how a port that ignores the box's offset reads it).</summary>
    /// <param name="b">The box.</param>
    /// <returns>The centred box.</returns>
    public static Box Centred(Box b)
    {
        var half = (b.Max - b.Min) * 0.5f;
        return new Box(-half, half);
    }

    /// <summary>Returns the rotation about z that carries the x axis to the rotated x axis's heading.</summary>
    /// <param name="q">A unit rotation.</param>
    /// <returns>Its heading as a rotation about z.</returns>
    public static Quaternion Heading(Quaternion q)
    {
        var x = Vector3.Transform(Vector3.UnitX, q);
        return Quaternion.CreateFromAxisAngle(Vector3.UnitZ, MathF.Atan2(x.Y, x.X));
    }

    private static Vector3 Permute(Vector3 v, int turn) => turn switch
    {
        0 => v,
        1 => new Vector3(v.Z, v.X, v.Y),
        _ => new Vector3(v.Y, v.Z, v.X),
    };

    private static float Degrees(float d) => d * MathF.PI / 180f;
}
