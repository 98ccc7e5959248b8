using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Walk generators: crossings of block lines at shallow angles, runs along a line, 4-block corners, ±1 ULP
/// oscillation across a line, multi-block jumps, starts at the map edge; bodies of 1–3 spheres, radii 0 to > 12 m.
/// </summary>
public static class WalkGens
{
    private const float Q = OutdoorGens.Quantum;

    /// <summary>Gets bodies: sphere 0 at the position, optional extra spheres offset by up to 2 m.</summary>
    public static Gen<BodySphere[]> Bodies { get; } =
        Gen.Zip(OutdoorGens.Radii, Gen.Frequency((6, Gen.Constant(0)), (3, Gen.Constant(1)), (1, Gen.Constant(2))))
            .SelectMany(t => Gen.ArrayOf(
                    Gen.Zip(Gen.Zip(Small(2), Small(2)), OutdoorGens.Radii).Select(e => new BodySphere(new Vector3(e.Item1.Item1, e.Item1.Item2, 0f), e.Item2)),
                    t.Item2)
                .Select(extra => (BodySphere[])[new BodySphere(new Vector3(0, 0, 0.5f), t.Item1), .. extra]));

    /// <summary>Gets walks of every class.</summary>
    public static Gen<Walk> Walks { get; } = Gen.Frequency(
        (3, Crossing()),
        (2, AlongLine()),
        (2, Corner()),
        (1, Oscillation()),
        (1, Jumps()),
        (1, MapEdge()),
        (2, Random()));

    /// <summary>Gets the arbitrary for walks, with the walk shrinker.</summary>
    public static Arbitrary<Walk> Arbitrary { get; } = Arb.From(Walks, WalkShrinker.Shrink);

    private static Gen<CellId> InnerCells => Gen.Zip(Gen.Zip(Gen.Choose(2, 0xFC), Gen.Choose(2, 0xFC)), Gen.Choose(1, 64))
        .Select(t => new CellId((byte)t.Item1.Item1, (byte)t.Item1.Item2, (ushort)t.Item2));

    private static Gen<float> Small(float metres) => Gen.Choose(-(int)(metres * 1024), (int)(metres * 1024)).Select(i => i * Q);

    private static Gen<Vector2[]> StepsOf(Gen<Vector2> step) => Gen.Choose(1, 8).SelectMany(n => Gen.ArrayOf(step, n));

    private static Gen<Walk> Make(Gen<CellId> cells, Gen<Vector3> starts, Gen<Vector2[]> steps) =>
        Gen.Zip(Gen.Zip(cells, starts), Gen.Zip(Bodies, steps)).Select(t => new Walk(t.Item1.Item1, t.Item1.Item2, t.Item2.Item1, t.Item2.Item2).Normalised());

    // Start within 3 m of a block line, move across it at a shallow angle.
    private static Gen<Walk> Crossing() => Make(
        InnerCells,
        Gen.Zip(Gen.Zip(Gen.Elements(0f, 192f), Small(3)), Gen.Zip(Gen.Choose(0, 191 * 1024).Select(i => i * Q), Gen.Elements(true, false)))
            .Select(t => t.Item2.Item2 ? new Vector3(t.Item1.Item1 + t.Item1.Item2, t.Item2.Item1, 0) : new Vector3(t.Item2.Item1, t.Item1.Item1 + t.Item1.Item2, 0)),
        StepsOf(Gen.Zip(Small(3), Small(0.25f)).SelectMany(t => Gen.Elements(new Vector2(t.Item1, t.Item2), new Vector2(t.Item2, t.Item1)))));

    // Exactly on a 24 m or 192 m line, moving along it.
    private static Gen<Walk> AlongLine() => Make(
        InnerCells,
        Gen.Zip(Gen.Choose(0, 8), Gen.Choose(0, 191 * 1024)).Select(t => new Vector3(t.Item2 * Q, t.Item1 * 24f, 0)),
        StepsOf(Small(6).Select(d => new Vector2(d, 0))));

    // Near a 4-block corner, small moves in any direction.
    private static Gen<Walk> Corner() => Make(
        InnerCells,
        Gen.Zip(Small(1), Small(1)).Select(t => new Vector3(t.Item1, t.Item2, 0)),
        StepsOf(Gen.Zip(Small(1), Small(1)).Select(t => new Vector2(t.Item1, t.Item2))));

    // One ULP either side of the block line x = 192, stepping by single ULPs.
    private static Gen<Walk> Oscillation() => Make(
        InnerCells,
        Gen.Zip(Gen.Elements(-2, -1, 0, 1), Gen.Choose(0, 191 * 1024)).Select(t => new Vector3(Ulps.Step(192f, t.Item1), t.Item2 * Q, 0)),
        StepsOf(Gen.Elements(1, -1, 2, -2).Select(u => new Vector2(Ulps.Step(192f, u) - 192f, 0))));

    // Jumps of several blocks.
    private static Gen<Walk> Jumps() => Make(
        InnerCells,
        Gen.Zip(Gen.Choose(0, 191 * 1024), Gen.Choose(0, 191 * 1024)).Select(t => new Vector3(t.Item1 * Q, t.Item2 * Q, 0)),
        StepsOf(Gen.Zip(Gen.Choose(-600, 600), Gen.Choose(-600, 600)).Select(t => new Vector2(t.Item1, t.Item2))));

    // Start in an edge block, move toward and off the map edge.
    private static Gen<Walk> MapEdge() => Make(
        Gen.Zip(Gen.Zip(Gen.Elements<byte>(0, 0xFE), Gen.Choose(0, 0xFE)), Gen.Elements(true, false))
            .Select(t => t.Item2 ? new CellId(t.Item1.Item1, (byte)t.Item1.Item2, 1) : new CellId((byte)t.Item1.Item2, t.Item1.Item1, 1)),
        Gen.Zip(Gen.Zip(Gen.Choose(0, 191 * 1024), Gen.Elements(0.5f, 3f, 189f, 191.5f)), Gen.Elements(true, false))
            .Select(t => t.Item2 ? new Vector3(t.Item1.Item1 * Q, t.Item1.Item2, 0) : new Vector3(t.Item1.Item2, t.Item1.Item1 * Q, 0)),
        StepsOf(Gen.Zip(Small(4), Small(4)).Select(t => new Vector2(t.Item1, t.Item2))));

    private static Gen<Walk> Random() => Make(
        InnerCells,
        Gen.Zip(Gen.Choose(0, 191 * 1024), Gen.Choose(0, 191 * 1024)).Select(t => new Vector3(t.Item1 * Q, t.Item2 * Q, 0)),
        StepsOf(Gen.Zip(Small(30), Small(30)).Select(t => new Vector2(t.Item1, t.Item2))));
}
