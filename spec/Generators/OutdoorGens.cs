using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Generators for outdoor queries and walks. Coordinates are multiples of 2⁻¹⁰ m (exact in float32 for the
/// magnitudes used, so shifting by whole cells or blocks is exact and frame changes lose nothing), plus exact
/// 24 m / 192 m lines and their ±1..4 ULP neighbours.
/// </summary>
public static class OutdoorGens
{
    /// <summary>Grid step of generated coordinates, metres (2⁻¹⁰).</summary>
    public const float Quantum = 1f / 1024f;

    /// <summary>Gets block-frame coordinates biased to lines: interior, exact lines, line ± small, line ± ULPs, just outside the block.</summary>
    public static Gen<float> Coordinates { get; } = Gen.Frequency(
        (6, Gen.Choose(0, 192 * 1024 - 1).Select(i => i * Quantum)),
        (3, Gen.Choose(0, 8).Select(k => k * 24f)),
        (5, Gen.Zip(Gen.Choose(0, 8), Gen.Choose(-2048, 2048)).Select(t => (t.Item1 * 24f) + (t.Item2 * Quantum))),
        (2, Gen.Zip(Gen.Elements(0f, 24f, 168f, 192f), Gen.Elements(-4, -3, -2, -1, 1, 2, 3, 4)).Select(t => Ulps.Step(t.Item1, t.Item2))),
        (2, Gen.Choose(-30 * 1024, 222 * 1024).Select(i => i * Quantum)));

    /// <summary>Gets radii: 0, typical, exactly 12 and just above, up to and beyond a cell (24 m).</summary>
    public static Gen<float> Radii { get; } = Gen.Frequency(
        (2, Gen.Constant(0f)),
        (6, Gen.Choose(1, 4 * 1024).Select(i => i * Quantum)),
        (2, Gen.Elements(0.5f, 12f, 12f + Quantum, 24f, 30f)),
        (2, Gen.Choose(4 * 1024, 26 * 1024).Select(i => i * Quantum)));

    /// <summary>Gets land cells away from the map edge (most), in edge blocks, and of every in-block index.</summary>
    public static Gen<CellId> Cells { get; } = Gen.Frequency(
        (8, Gen.Zip(Gen.Zip(Gen.Choose(1, 0xFD), Gen.Choose(1, 0xFD)), Gen.Choose(1, 64)).Select(t => new CellId((byte)t.Item1.Item1, (byte)t.Item1.Item2, (ushort)t.Item2))),
        (2, Gen.Zip(Gen.Zip(Gen.Elements(0, 0xFE), Gen.Choose(0, 0xFE)), Gen.Zip(Gen.Choose(1, 64), Gen.Elements(true, false)))
            .Select(t => t.Item2.Item2
                ? new CellId((byte)t.Item1.Item1, (byte)t.Item1.Item2, (ushort)t.Item2.Item1)
                : new CellId((byte)t.Item1.Item2, (byte)t.Item1.Item1, (ushort)t.Item2.Item1))));

    /// <summary>
    /// Gets the positions a query may come from (facts §6.12, §4 step 3): land cells (most), an env cell or the block id
    /// 0xFFFF of an on-map block (both reach the land under them), id 0, a malformed low word, a 0xFF block byte, and
    /// every bound of the low-word ranges (<see cref="LandGens.LowWordBounds"/>: 0x0100 is the first indoor position).
    /// </summary>
    public static Gen<CellId> Positions { get; } = Gen.Frequency(
        (26, Cells),
        (2, Gen.Zip(Cells, Gen.Choose(0x100, 0xFFFD)).Select(t => new CellId(t.Item1.BlockX, t.Item1.BlockY, (ushort)t.Item2))),
        (2, Cells.Select(c => new CellId(c.BlockX, c.BlockY, 0xFFFF))),
        (1, Gen.Constant(CellId.None)),
        (1, Gen.Zip(Cells, Gen.Elements(0, 65, 0xFF, 0xFFFE)).Select(t => new CellId(t.Item1.BlockX, t.Item1.BlockY, (ushort)t.Item2))),
        (1, Gen.Zip(Cells, Gen.Elements(LandGens.LowWordBounds.ToArray())).Select(t => new CellId(t.Item1.BlockX, t.Item1.BlockY, t.Item2))),
        (1, Gen.Zip(Cells, Gen.Elements(true, false)).Select(t => t.Item2 ? new CellId(0xFF, t.Item1.BlockY, t.Item1.Low) : new CellId(t.Item1.BlockX, 0xFF, t.Item1.Low))));

    /// <summary>
    /// Gets the coordinates only the LandDefs invariants used to see (facts §6.12, §6.17): NaN, ±∞, subnormals and
    /// huge values (|v| ≤ 10¹⁵, so ⌊v/24⌋ stays far inside the 64-bit range retail converts through).
    /// </summary>
    public static Gen<float> ExtremeCoordinates { get; } = Gen.Elements(
        float.NaN, float.PositiveInfinity, float.NegativeInfinity, float.Epsilon, -float.Epsilon, 1e-40f, -1e-40f, 1e6f, -1e6f, 3.4e9f, -7.2e12f, 1e15f, -1e15f);

    /// <summary>
    /// Gets centres within rounding of a cell corner (issue #29, facts §5.5): one coordinate on a cell line, the other
    /// a tenth to half a micrometre off the block's own line 0 — the only place where float32 can tell such a point from
    /// the corner, and where retail's terrain triangles accept points that the closed square does not
    /// (docs/conformance.md, "Land-cell edges").
    /// </summary>
    public static Gen<Sphere> NearCorners { get; } =
        Gen.Zip(Gen.Zip(Gen.Choose(0, 8), Gen.Elements(-5e-7f, -2e-7f, -1e-7f, 1e-7f, 5e-7f)), Gen.Zip(Gen.Elements(true, false), Radii))
            .Select(t =>
            {
                float line = 24f * t.Item1.Item1, off = t.Item1.Item2;
                var centre = t.Item2.Item1 ? new Vector3(off, line, 0.5f) : new Vector3(line, off, 0.5f);
                return new Sphere(centre, t.Item2.Item2);
            });

    /// <summary>Gets spheres (z small, irrelevant to outdoor membership).</summary>
    public static Gen<Sphere> Spheres { get; } = Gen.Frequency(
        (20, Gen.Zip(Gen.Zip(Coordinates, Coordinates), Radii).Select(t => new Sphere(new Vector3(t.Item1.Item1, t.Item1.Item2, 0.5f), t.Item2))),
        (3, Gen.Zip(Gen.Zip(Coordinates, Coordinates), Gen.Choose(0, 3)).Select(t => Touching(t.Item1.Item1, t.Item1.Item2, t.Item2))),
        (2, Gen.Zip(Gen.Zip(ExtremeCoordinates, Coordinates), Gen.Zip(Radii, Gen.Choose(0, 2))).Select(t => Extreme(t.Item1.Item1, t.Item1.Item2, t.Item2.Item1, t.Item2.Item2))),
        (1, NearCorners));

    /// <summary>Gets outdoor queries: no spheres (the position's own point is used, facts §3.3 step 3), or 1–3 spheres (multi-sphere bodies).</summary>
    public static Gen<OutdoorCase> Cases { get; } =
        Gen.Zip(Gen.Zip(Positions, Gen.Zip(Coordinates, Coordinates)), Gen.Frequency((2, Gen.Constant(0)), (18, Gen.Constant(1)), (9, Gen.Constant(2)), (3, Gen.Constant(3))))
            .SelectMany(t => Gen.ArrayOf(Spheres, t.Item2).Select(s => new OutdoorCase(t.Item1.Item1, s) { Origin = s.Length == 0 ? new Vector3(t.Item1.Item2.Item1, t.Item1.Item2.Item2, 0.5f) : Vector3.Zero }));

    // A disc that exactly touches one edge of its cell (facts §3.2, §6.7: the tests are strict, so it adds nothing
    // there): r is the exact distance from the centre to the west (0), east (1), south (2) or north (3) line. Both are
    // multiples of 2⁻¹⁰ below 2¹³, so the float32 difference is exact.
    private static Sphere Touching(float x, float y, int edge)
    {
        float v = edge < 2 ? x : y;
        float inCell = v - (24f * MathF.Floor(v / 24f));
        if (inCell < 0)
        {
            // v is a tiny negative (−1 ULP of 0): v / 24 underflows to −0, so the floor misses the cell west of the line.
            // Its in-cell coordinate 24 + v rounds to 24; a negative radius (−1.4e-45) is no body (formats/Values/SphereRadius).
            inCell += 24f;
        }

        float r = edge % 2 == 0 ? inCell : 24f - inCell;
        return new Sphere(new Vector3(x, y, 0.5f), r == 0 ? 24f : r);
    }

    private static Sphere Extreme(float extreme, float other, float r, int axis) => axis switch
    {
        0 => new Sphere(new Vector3(extreme, other, 0.5f), r),
        1 => new Sphere(new Vector3(other, extreme, 0.5f), r),
        _ => new Sphere(new Vector3(extreme, extreme, 0.5f), r),
    };

    /// <summary>Gets the arbitrary for outdoor queries.</summary>
    public static Arbitrary<OutdoorCase> Arbitrary { get; } = Arb.From(Cases, OutdoorShrinker.Shrink);

}
