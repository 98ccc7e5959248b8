using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// LandDefs statements of facts §2 checked at the exact edges the mutation run found untested: the map square's
/// upper bound in x, GetBlockOffset over every block byte (0xFF and the 0xFFFF high word included) and InBlock's
/// strict upper bound in y.
/// </summary>
public sealed class LandDefsMutationTests
{
    [FixedSeedProperty(0x1A4D_0001, DisplayName = "facts §2 in_bounds: (x, y) is on the map exactly when 0 <= x < 2040 and 0 <= y < 2040, each axis on its own")]
    public Property InBounds_IsTheHalfOpenSquareOnEachAxis() =>
        Prop.ForAll(Gen.Zip(EdgeInts, EdgeInts).ToArbitrary(), t =>
        {
            var (x, y) = t;
            bool expected = x >= 0 && x < 2040 && y >= 0 && y < 2040;
            return LandDefs.InBounds(x, y) == expected
                && new Lcoord(x, y).IsOnMap == expected
                && LandDefs.LcoordToGid(x, y).IsNone == !expected;
        });

    [FixedSeedProperty(0x1A4D_0002, DisplayName = "facts §2 lcoord_to_gid: 0 off the map, else block (x>>3, y>>3) and low word 1 + 8·(x&7) + (y&7), at both map edges")]
    public Property LcoordToGid_IsTheDocumentedBitsAtTheEdges() =>
        Prop.ForAll(Gen.Zip(EdgeInts, EdgeInts).ToArbitrary(), t =>
        {
            var (x, y) = t;
            var id = LandDefs.LcoordToGid(x, y);
            if (!LandDefs.InBounds(x, y))
            {
                return id == CellId.None;
            }

            return id.BlockX == x >> 3 && id.BlockY == y >> 3 && id.Low == 1 + (8 * (x & 7)) + (y & 7)
                && LandDefs.GidToLcoord(id, out var back) && back == new Lcoord(x, y);
        });

    [FixedSeedProperty(0x1A4D_0003, DisplayName = "facts §2 GetBlockOffset: 192·(Δbx, Δby, 0) for any two ids, zero exactly for the same high word; retail validates nothing (0xFF bytes count)")]
    public Property GetBlockOffset_IsTheBlockStepForAnyBytes() =>
        Prop.ForAll(Gen.Zip(AnyIds, AnyIds).ToArbitrary(), t =>
        {
            var (from, to) = t;
            var offset = LandDefs.GetBlockOffset(from, to);
            var expected = new Vector3(192f * (to.BlockX - from.BlockX), 192f * (to.BlockY - from.BlockY), 0f);
            bool sameBlock = from.Landblock == to.Landblock;
            return offset == expected && (offset == Vector3.Zero) == sameBlock
                && LandDefs.GetBlockOffset(to, from) == -expected;
        });

    [FixedSeedProperty(0x1A4D_0004, DisplayName = "facts §2 InBlock: false if x < r or y < r, else x < 192 - r and y < 192 - r (lower bound inclusive, upper strict, each axis)")]
    public Property InBlock_BoundsAreInclusiveBelowStrictAboveOnEachAxis() =>
        Prop.ForAll(Gen.Zip(Radii, Gen.Zip(EdgeChoices, EdgeChoices)).ToArbitrary(), t =>
        {
            var (r, (cx, cy)) = t;
            float x = Place(cx, r);
            float y = Place(cy, r);
            bool expected = !(x < r || y < r) && x < 192f - r && y < 192f - r;
            return LandDefs.InBlock(new Vector3(x, y, 7f), r) == expected;
        });

    /// <summary>Ints around both map edges (−1, 0, 2039, 2040) and far off the map.</summary>
    private static Gen<int> EdgeInts { get; } = Gen.Frequency(
        (3, Gen.Elements(-1, 0, 1, 2038, 2039, 2040, 2041)),
        (2, Gen.Choose(0, 2039)),
        (1, Gen.Elements(int.MinValue, -2040, 4079, 4080, int.MaxValue)));

    /// <summary>Any ids, with block bytes biased to 0x00, 0xFE and 0xFF (so 0xFFFF high words occur) and often equal blocks.</summary>
    private static Gen<CellId> AnyIds { get; } = Gen.Frequency(
        (3, FixedSeed.Zip(FixedSeed.Bytes, FixedSeed.Bytes, Gen.Choose(0, 0xFFFF)).Select(t => new CellId(t.Item1, t.Item2, (ushort)t.Item3))),
        (1, Gen.Elements(CellId.None, new CellId(0xFFFF0001), new CellId(0xFFFFFFFF), new CellId(0x00FF0040), new CellId(0xFF000100))));

    /// <summary>Radii: zero, small, half a cell, and arbitrary below 96 m.</summary>
    private static Gen<float> Radii { get; } = Gen.Frequency(
        (2, Gen.Elements(0f, 0.5f, 1f, 12f)),
        (1, Gen.Choose(1, 95_000).Select(i => i / 1000f)));

    /// <summary>Where a coordinate sits relative to r and 192 − r: on, one ULP either side, well inside, well outside.</summary>
    private static Gen<int> EdgeChoices { get; } = Gen.Choose(0, 7);

    private static float Place(int choice, float r) => choice switch
    {
        0 => r,
        1 => MathF.BitDecrement(r),
        2 => MathF.BitIncrement(r),
        3 => 192f - r,
        4 => MathF.BitDecrement(192f - r),
        5 => MathF.BitIncrement(192f - r),
        6 => 96f,
        _ => 192f + r,
    };
}
