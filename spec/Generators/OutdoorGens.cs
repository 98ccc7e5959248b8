using System.Numerics;
using AcPhys.Core;
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

    /// <summary>Gets spheres (z small, irrelevant to outdoor membership).</summary>
    public static Gen<Sphere> Spheres { get; } =
        Gen.Zip(Gen.Zip(Coordinates, Coordinates), Radii).Select(t => new Sphere(new Vector3(t.Item1.Item1, t.Item1.Item2, 0.5f), t.Item2));

    /// <summary>Gets outdoor queries with 1–3 spheres (multi-sphere bodies).</summary>
    public static Gen<OutdoorCase> Cases { get; } =
        Gen.Zip(Cells, Gen.Frequency((6, Gen.Constant(1)), (3, Gen.Constant(2)), (1, Gen.Constant(3))))
            .SelectMany(t => Gen.ArrayOf(Spheres, t.Item2).Select(s => new OutdoorCase(t.Item1, s)));

    /// <summary>Gets the arbitrary for outdoor queries.</summary>
    public static Arbitrary<OutdoorCase> Arbitrary { get; } = Arb.From(Cases, OutdoorShrinker.Shrink);

}
