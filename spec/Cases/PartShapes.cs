using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The shape of the part a body sphere stands for at a step of a scene walk: its kind, rotation and local box, chosen
/// from the step index and the sphere's index alone (no randomness: the shrinker's smaller walk has the same parts at
/// the steps it keeps). Boxes are retail-like (issue 53): half of them tidy (well inside the sphere), a quarter
/// poking out of it, an eighth flat plates and an eighth long sticks; all differ per axis and sit off the part's
/// origin, yawed on every step and pitched and rolled too on odd steps.
/// </summary>
/// <remarks>
/// A retail part's box is the bounding box of a mesh whose bounding sphere is the part's sphere: it holds the centre
/// and lies within [−r, r]³, so its corners reach from inside the sphere to √3·r. A poking box's corners reach 0.86·r
/// to 1.65·r, so its hull in a cell's frame can cross a portal's plane while the part's centre is farther than r + EPS
/// from it: the sphere gate (facts §5.2, §5.3) and the box test then disagree, and the order of the two tests, a
/// two-sided gate and a skipped box test are told apart (spec/Faults/PartsShapeFaults). The oracles test the gate and
/// the box themselves.
/// </remarks>
internal static class PartShapes
{
    /// <summary>A bound on |corner| / r of every local box: poking boxes reach 1.65·r (below √3 ≈ 1.73).</summary>
    public const float Reach = 1.65f;

    private static readonly Vector3 TidyHalf = new(0.28f, 0.18f, 0.12f);
    private static readonly Vector3 TidyOffset = new(0.10f, 0.06f, 0.04f);

    // Per axis, how far a poking box reaches from the centre on its far side (≤ 1: within [−r, r]³); |corner| 0.86·r to 1.65·r.
    private static readonly Vector3[] PokingReach =
    [
        new(0.97f, 0.96f, 0.92f), new(0.62f, 0.45f, 0.40f), new(0.90f, 0.75f, 0.60f), new(0.99f, 0.55f, 0.95f), new(0.80f, 0.97f, 0.30f),
    ];

    // A flat plate (0.07·r thick) and a long stick (1.9·r long), each off-centre by a little.
    private static readonly Vector3 FlatHalf = new(0.62f, 0.55f, 0.035f);
    private static readonly Vector3 FlatOffset = new(0.08f, 0.05f, 0.01f);
    private static readonly Vector3 LongHalf = new(0.95f, 0.08f, 0.05f);
    private static readonly Vector3 LongOffset = new(0.03f, 0.02f, 0.01f);

    /// <summary>Returns the kind of part <paramref name="k"/>'s box at a step: over every 8 steps of a part, 4 tidy, 2 poking, 1 flat, 1 long.</summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index (0 = the anchor).</param>
    /// <returns>The kind.</returns>
    public static PartShape Kind(int step, int k) => (((step * 5) + (k * 3)) & 7) switch
    {
        < 4 => PartShape.Tidy,
        < 6 => PartShape.Poking,
        6 => PartShape.Flat,
        _ => PartShape.Long,
    };

    /// <summary>
    /// Returns whether part <paramref name="k"/> at a step is Always2D: 1 in 4 non-anchor parts of every step, and the
    /// anchor on 1 step in 4. Retail's parts add_all_outside_cells takes such a part's square ±r around its raw origin,
    /// not its box (facts §3.4); the portal and door tests take its box all the same (§5.2, §5.3).
    /// </summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index (0 = the anchor).</param>
    /// <returns>True for an Always2D part.</returns>
    public static bool Always2D(int step, int k) => k == 0 ? (step & 3) == 2 : ((step + (k * 3)) & 3) == 1;

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

    /// <summary>Returns the local box of part <paramref name="k"/> at a step, of its <see cref="Kind"/>: half extents and an offset permuted over the axes by (step + k) mod 3, the offset's signs by step and part.</summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index.</param>
    /// <param name="radius">The sphere's radius.</param>
    /// <returns>The box (never centred on the origin; it holds the origin and lies within [−r, r]³).</returns>
    public static Box Bounds(int step, int k, float radius)
    {
        var (half, offset) = Kind(step, k) switch
        {
            PartShape.Poking => Poking(step, k),
            PartShape.Flat => (FlatHalf, FlatOffset),
            PartShape.Long => (LongHalf, LongOffset),
            _ => (TidyHalf, TidyOffset),
        };
        int turn = (step + k) % 3;
        int signs = (step * 3) + k;
        var signed = Permute(offset, turn) * new Vector3((signs & 1) == 0 ? 1 : -1, (signs & 2) == 0 ? 1 : -1, (signs & 4) == 0 ? 1 : -1);
        var h = Permute(half, turn);
        return new Box((signed - h) * radius, (signed + h) * radius);
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

    // A poking box: reach a per axis (one of PokingReach by step), offset 0.15·a toward it, half extents a − |offset|.
    private static (Vector3 Half, Vector3 Offset) Poking(int step, int k)
    {
        var a = PokingReach[((step / 3) + k) % PokingReach.Length];
        var offset = a * 0.15f;
        return (a - offset, offset);
    }

    private static Vector3 Permute(Vector3 v, int turn) => turn switch
    {
        0 => v,
        1 => new Vector3(v.Z, v.X, v.Y),
        _ => new Vector3(v.Y, v.Z, v.X),
    };

    private static float Degrees(float d) => d * MathF.PI / 180f;
}
