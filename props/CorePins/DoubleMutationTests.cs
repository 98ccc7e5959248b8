using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The double-precision reference where the 2026-12-01 mutation run found no test: the current-first pick, the
/// no-sphere origin cell, and the out-of-range id. On points float32 holds exactly (multiples of 1/4 m here), the
/// double mode must give retail's float32 answer bit for bit (docs/numerics.md), so float32 is the oracle.
/// </summary>
public sealed class DoubleMutationTests
{
    [FixedSeedProperty(0xD0B1_0001, DisplayName = "facts §4: on exact points, the double pick equals the float32 pick under both policies, current-first included")]
    public Property PickOutdoorDouble_EqualsFloatOnExactPoints() =>
        Prop.ForAll(PickCases.ToArbitrary(), c =>
        {
            var array = new CellArray();
            OutdoorCells.AddAllOutsideCells(array, c.Position, Vector3.Zero, [new Sphere(c.Center, c.Radius)], c.Land);
            var current = c.CurrentIndex < 0 || array.Count == 0 ? c.Position : array[c.CurrentIndex % array.Count].Id;
            var retail = ContainingCell.PickOutdoor(array, c.Position, c.Center, PickPolicy.Retail, current);
            var first = ContainingCell.PickOutdoor(array, c.Position, c.Center, PickPolicy.CurrentFirst, current);
            bool ok = ContainingCell.PickOutdoorDouble(array, c.Position, c.Center, PickPolicy.Retail, current) == retail
                && ContainingCell.PickOutdoorDouble(array, c.Position, c.Center, PickPolicy.CurrentFirst, current) == first;
            return ok.Classify(first != retail, "current-first decides").Classify(retail.IsNone, "no pick");
        });

    [FixedSeedProperty(0xD0B1_0002, DisplayName = "facts §3.1 (no spheres): on exact origins, the double mode adds the same single origin cell as float32, or nothing off the map")]
    public Property NoSphereOrigin_DoubleEqualsFloat() =>
        Prop.ForAll(PickCases.ToArbitrary(), c =>
        {
            var single = new CellArray();
            var exact = new CellArray();
            OutdoorCells.AddAllOutsideCells(single, c.Position, c.Center, ReadOnlySpan<Sphere>.Empty, c.Land);
            OutdoorCells.AddAllOutsideCells(exact, c.Position, c.Center, ReadOnlySpan<Sphere>.Empty, c.Land, OutdoorFidelity.Double with { DropUnloadedCells = c.Drop });
            if (c.Drop)
            {
                single.Reset();
                OutdoorCells.AddAllOutsideCells(single, c.Position, c.Center, ReadOnlySpan<Sphere>.Empty, c.Land, OutdoorFidelity.Ace);
            }

            bool same = single.ToIdArray().SequenceEqual(exact.ToIdArray()) && Loaded(single).SequenceEqual(Loaded(exact));
            return same.Classify(exact.Count == 0, "off the map or dropped");
        });

    [FixedSeedProperty(0xD0B1_0003, DisplayName = "facts §2.1 step 1: for an out-of-range low word the double re-seat fails as float32 does: None, and the point untouched (not EPS-snapped)")]
    public Property AdjustToOutsideInDouble_OutOfRangeLeavesThePoint() =>
        Prop.ForAll(FixedSeed.Zip(OutOfRangeIds, Tiny, Tiny).ToArbitrary(), t =>
        {
            var (id, x, y) = t;
            var fid = id;
            float fx = x, fy = y;
            bool floatOk = LandDefs.AdjustToOutside(ref fid, ref fx, ref fy);
            var did = id;
            double dx = x, dy = y;
            bool doubleOk = LandDefs.AdjustToOutsideInDouble(ref did, ref dx, ref dy);
            return !floatOk && !doubleOk && did == CellId.None && fid == CellId.None && dx == x && dy == y && fx == x && fy == y;
        });

    [FixedSeedProperty(0xD0B1_0004, DisplayName = "facts §2.1 step 4: the double re-seat names the float32 re-seat's cell and re-bases each axis exactly, v − 192·(block step), into [0, 192)")]
    public Property AdjustToOutsideInDouble_RebasesEachAxisExactly() =>
        Prop.ForAll(PickCases.ToArbitrary(), c =>
        {
            CellId single = c.Position, exact = c.Position;
            float fx = c.Center.X, fy = c.Center.Y;
            double dx = c.Center.X, dy = c.Center.Y;
            bool ok = LandDefs.AdjustToOutside(ref single, ref fx, ref fy);
            if (LandDefs.AdjustToOutsideInDouble(ref exact, ref dx, ref dy) != ok || exact != single)
            {
                return false.Label($"{c.Position} {c.Center}: {exact} vs float32 {single}");
            }

            // The snap (|v| < EPS → 0) happens before the re-base, so the expected value starts from the snapped input.
            double Snapped(float v) => Math.Abs(v) < LandDefs.Epsilon ? 0 : v;
            double ex = Snapped(c.Center.X) - (LandDefs.BlockLength * (exact.BlockX - c.Position.BlockX));
            double ey = Snapped(c.Center.Y) - (LandDefs.BlockLength * (exact.BlockY - c.Position.BlockY));
            bool rebased = !ok || (dx == ex && dy == ey && dx >= 0 && dx < 192 && dy >= 0 && dy < 192);
            return rebased.Label($"{c.Position} {c.Center} → {exact} ({dx}, {dy}), expected ({ex}, {ey})")
                .Classify(ok && exact.Landblock != c.Position.Landblock, "moved to another block").Classify(!ok, "off the map");
        });

    // Positions anywhere on the map (edges often), centres on a 1/4 m grid around the block (24 m lines often),
    // radii up to two cells, a current cell drawn from the array, and a landscape with some blocks unloaded.
    private static Gen<PickCase> PickCases { get; } =
        from blockX in Gen.Frequency((1, Gen.Elements(0, 1, 253, 254, 255)), (3, Gen.Choose(0, 254)))
        from blockY in Gen.Frequency((1, Gen.Elements(0, 1, 253, 254, 255)), (3, Gen.Choose(0, 254)))
        from low in Gen.Frequency((4, Gen.Choose(1, 64)), (1, Gen.Elements(0xFFFF, 0x100, 0x0, 0x41)))
        from x in Coordinate
        from y in Coordinate
        from radius in Gen.Elements(0f, 0.25f, 1f, 12f, 24f, 47.75f)
        from currentIndex in Gen.Choose(-1, 40)
        from unloaded in Gen.Choose(0, 3)
        from drop in Gen.Elements(true, false)
        let position = new CellId((uint)((blockX << 24) | (blockY << 16) | low))
        select new PickCase(position, new Vector3(x, y, 0), radius, currentIndex, Landscape(position, unloaded), drop);

    private static Gen<float> Coordinate { get; } = Gen.Frequency(
        (3, Gen.Choose(-9, 17).Select(i => i * 24f)),
        (1, Gen.Elements(-0.0001f, 0.0001f, 191.75f, 192.25f, -0.25f)),
        (3, Gen.Choose(-800, 1600).Select(i => i * 0.25f)));

    private static Gen<CellId> OutOfRangeIds { get; } =
        from block in Gen.Choose(0, 0xFFFF)
        from low in Gen.Elements(0, 0x41, 0x42, 0x80, 0xFF, 0xFFFE)
        select new CellId((uint)((block << 16) | low));

    private static Gen<float> Tiny { get; } = Gen.Elements(0f, 0.00005f, -0.00005f, 0.0001f, -0.0001f, 12f, -200f);

    private static CellScene Landscape(CellId position, int unloaded)
    {
        // Every block within one of the position's, except the first `unloaded` of the east, north and north-east ones.
        var blocks = new List<LandblockId>();
        int skipped = 0;
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                int x = position.BlockX + dx, y = position.BlockY + dy;
                if (x < 0 || y < 0 || x > 255 || y > 255)
                {
                    continue;
                }

                if ((dx > 0 || dy > 0) && skipped < unloaded)
                {
                    skipped++;
                    continue;
                }

                blocks.Add(new LandblockId((byte)x, (byte)y));
            }
        }

        return new CellScene(blocks, [], []);
    }

    private static bool[] Loaded(CellArray array) => [.. CellArrays.Entries(array).Select(e => e.Loaded)];

    private sealed record PickCase(CellId Position, Vector3 Center, float Radius, int CurrentIndex, CellScene Land, bool Drop);
}
