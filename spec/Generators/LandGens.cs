using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Generators for the LandDefs invariants, biased to the classes that matter: exact 24 m and 192 m lines and their
/// float32 neighbours (±1..4 ULP), the EPS snap band and its edges, negatives, map edges, huge magnitudes,
/// NaN/±Inf/−0/subnormals, 0xFF block bytes and malformed low words.
/// </summary>
internal static class LandGens
{
    /// <summary>Gets block-frame coordinates.</summary>
    public static Gen<float> Coordinates { get; } = Gen.Frequency(
        (10, Gen.Choose(0, 191_999_999).Select(i => i / 1e6f)),
        (8, Gen.Choose(-16, 16).Select(k => k * 24f)),
        (5, Gen.Choose(-8, 8).Select(k => k * 192f)),
        (10, Gen.Zip(Gen.Choose(-16, 16), Gen.Elements(-4, -3, -2, -1, 1, 2, 3, 4)).Select(t => Ulps.Step(t.Item1 * 24f, t.Item2))),
        (8, Gen.Choose(-199_999, 199_999).Select(i => i * 1e-9f)),
        (4, Gen.Zip(Gen.Elements(LandDefs.Epsilon, -LandDefs.Epsilon), Gen.Choose(-4, 4)).Select(t => Ulps.Step(t.Item1, t.Item2))),
        (6, Gen.Choose(1, 200_000_000).Select(i => -i / 1e6f)),
        (6, Gen.Zip(Gen.Choose(-50_000, 50_000), Gen.Choose(0, 999)).Select(t => t.Item1 + (t.Item2 / 1000f))),
        (3, Gen.Elements(1e6f, -1e6f, 1e7f, -1e30f, 3e38f, float.MaxValue, float.MinValue)),
        (4, Gen.Elements(float.NaN, float.PositiveInfinity, float.NegativeInfinity)),
        (3, Gen.Frequency(
            (1, Gen.Elements(-0f, float.Epsilon, -float.Epsilon)),
            (2, Gen.Zip(Gen.Choose(1, 0x7FFFFF), Gen.Elements(0, int.MinValue)).Select(t => BitConverter.Int32BitsToSingle(t.Item1 | t.Item2))))));

    /// <summary>
    /// Gets the low words on both sides of every bound of cell_in_range (facts §1.1: land 0x0001..0x0040, env
    /// 0x0100..0xFFFD, the block 0xFFFF): each range's first and last member and its outer neighbours. A uniform draw
    /// over 0x100..0xFFFD almost never lands on 0x0100 itself, so a port's <c>&gt; 0x100</c> went unseen (docs/ports.md §12). Declared before <see cref="Cells"/>, which draws from it.
    /// </summary>
    public static IReadOnlyList<ushort> LowWordBounds { get; } = [0x0000, 0x0001, 0x0040, 0x0041, 0x00FF, 0x0100, 0xFFFD, 0xFFFE, 0xFFFF];

    /// <summary>Gets cell ids of every class: land cells anywhere, edge blocks, 0xFF bytes, env, block, malformed, zero, and every bound of the low-word ranges (<see cref="LowWordBounds"/>) on an on-map block.</summary>
    public static Gen<CellId> Cells { get; } = Gen.Frequency(
        (10, Gen.Zip(Gen.Zip(Bytes(0, 0xFE), Bytes(0, 0xFE)), Gen.Choose(1, 64)).Select(t => new CellId(t.Item1.Item1, t.Item1.Item2, (ushort)t.Item2))),
        (3, Gen.Zip(Gen.Zip(Gen.Elements<byte>(0, 0xFE), Bytes(0, 0xFE)), Gen.Zip(Gen.Choose(1, 64), Gen.Elements(true, false)))
            .Select(t => t.Item2.Item2
                ? new CellId(t.Item1.Item1, t.Item1.Item2, (ushort)t.Item2.Item1)
                : new CellId(t.Item1.Item2, t.Item1.Item1, (ushort)t.Item2.Item1))),
        (3, Gen.Zip(Gen.Zip(Bytes(0, 0xFF), Gen.Elements(true, false)), Gen.Elements<ushort>(1, 8, 57, 64, 0x100, 0xFFFF))
            .Select(t => t.Item1.Item2 ? new CellId(0xFF, t.Item1.Item1, t.Item2) : new CellId(t.Item1.Item1, 0xFF, t.Item2))),
        (3, Gen.Zip(Gen.Zip(Bytes(0x80, 0xFE), Bytes(0x80, 0xFE)), Gen.Choose(1, 64)).Select(t => new CellId(t.Item1.Item1, t.Item1.Item2, (ushort)t.Item2))),
        (2, Gen.Zip(Gen.Zip(Bytes(0, 0xFE), Bytes(0, 0xFE)), Gen.Choose(0x100, 0xFFFD)).Select(t => new CellId(t.Item1.Item1, t.Item1.Item2, (ushort)t.Item2))),
        (1, Gen.Zip(Bytes(0, 0xFE), Bytes(0, 0xFE)).Select(t => new CellId(t.Item1, t.Item2, 0xFFFF))),
        (1, Gen.Zip(Gen.Zip(Bytes(0, 0xFE), Bytes(0, 0xFE)), Gen.Elements(LowWordBounds.ToArray())).Select(t => new CellId(t.Item1.Item1, t.Item1.Item2, t.Item2))),
        (2, Gen.Zip(Gen.Zip(Bytes(0, 0xFE), Bytes(0, 0xFE)), Gen.Elements<ushort>(0, 0x41, 0x80, 0xFF, 0xFFFE)).Select(t => new CellId(t.Item1.Item1, t.Item1.Item2, t.Item2))),
        (1, Gen.Constant(CellId.None)));

    /// <summary>Gets lcoords: on the map, on its edges (0, 2039), just off it (−1, 2040) and far off it.</summary>
    public static Gen<Lcoord> Lcoords { get; } = Gen.Frequency(
        (6, Gen.Zip(Gen.Choose(0, 2039), Gen.Choose(0, 2039)).Select(t => new Lcoord(t.Item1, t.Item2))),
        (4, Gen.Zip(Gen.Zip(Gen.Elements(0, 2039), Gen.Choose(0, 2039)), Gen.Elements(true, false)).Select(t => t.Item2 ? new Lcoord(t.Item1.Item1, t.Item1.Item2) : new Lcoord(t.Item1.Item2, t.Item1.Item1))),
        (3, Gen.Zip(Gen.Zip(Gen.Elements(-1, 2040), Gen.Choose(-1, 2040)), Gen.Elements(true, false)).Select(t => t.Item2 ? new Lcoord(t.Item1.Item1, t.Item1.Item2) : new Lcoord(t.Item1.Item2, t.Item1.Item1))),
        (1, Gen.Zip(Gen.Choose(-100_000, 100_000), Gen.Choose(-100_000, 100_000)).Select(t => new Lcoord(t.Item1, t.Item2))));

    /// <summary>Gets whole LandDefs cases.</summary>
    public static Gen<LandCase> Cases { get; } =
        Gen.Zip(Gen.Zip(Cells, Coordinates), Gen.Zip(Coordinates, Lcoords))
            .Select(t => new LandCase(t.Item1.Item1, t.Item1.Item2, t.Item2.Item1, t.Item2.Item2));

    /// <summary>Gets the arbitrary for cases: <see cref="Cases"/> with <see cref="LandCaseShrinker"/>.</summary>
    public static Arbitrary<LandCase> Arbitrary { get; } = Arb.From(Cases, LandCaseShrinker.Shrink);

    private static Gen<byte> Bytes(int lo, int hi) => Gen.Choose(lo, hi).Select(i => (byte)i);

}
