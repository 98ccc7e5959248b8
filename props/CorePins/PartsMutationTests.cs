using System.Numerics;
using AcPhys.Core;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The parts / bounding-box variant (facts §3.4, §3.5, §5.8, §7 #3–#4) where the mutation run found it untested:
/// the latch, no parts, ACE's same-block guard, a part with a non-finite extent, and the frame transforms.
/// </summary>
public sealed class PartsMutationTests
{
    private static readonly CellId Anchor = new(0xA9B40012);

    [Fact(DisplayName = "facts §3.4 step 1 and §3.5: the parts variant sets the latch first, even for no parts, and is a no-op while it is set")]
    public void PartsAddAllOutsideCells_SetsAndHonoursTheLatch()
    {
        var empty = new CellArray();
        OutdoorParts.AddAllOutsideCells(empty, ReadOnlySpan<Part>.Empty, Anchor, OpenLand.Instance);
        Assert.True(empty.AddedOutside);
        Assert.Equal(0, empty.Count);

        var once = new CellArray();
        Part[] parts = [Box(Anchor, new Vector3(60f, 36f, 0f), 1f)];
        OutdoorParts.AddAllOutsideCells(once, parts, Anchor, OpenLand.Instance);
        Assert.True(once.AddedOutside);
        Assert.Equal([Anchor], once.ToIdArray());

        Part[] elsewhere = [Box(new CellId(0x10100001), new Vector3(12f, 12f, 0f), 1f)];
        OutdoorParts.AddAllOutsideCells(once, elsewhere, Anchor, OpenLand.Instance);
        Assert.Equal([Anchor], once.ToIdArray());
    }

    [FixedSeedProperty(0x9A47_0001, DisplayName = "facts §7 #3: with ACE's guard, add_cell_block keeps exactly the cells in the caller's landblock, in x-outer y-inner order")]
    public Property AddCellBlock_AceGuardKeepsTheCallersBlock() =>
        Prop.ForAll(Gen.Zip(Gen.Zip(Gen.Choose(1350, 1362), Gen.Choose(1438, 1450)), Gen.Elements(true, false)).ToArbitrary(), t =>
        {
            var ((x0, y0), guard) = t;
            var caller = LandDefs.LcoordToGid(1356, 1444);
            var array = new CellArray();
            OutdoorParts.AddCellBlock(array, x0, y0, x0 + 3, y0 + 3, caller, OpenLand.Instance, guard);
            var expected = new List<CellId>();
            for (int i = x0; i <= x0 + 3; i++)
            {
                for (int j = y0; j <= y0 + 3; j++)
                {
                    var id = LandDefs.LcoordToGid(i, j);
                    if (!guard || id.Landblock == caller.Landblock)
                    {
                        expected.Add(id);
                    }
                }
            }

            return array.ToIdArray().SequenceEqual(expected);
        });

    [Fact(DisplayName = "facts §7 #3–#4: PartsFidelity.Ace turns on the same-block guard and every-part anchors; Retail neither")]
    public void PartsFidelity_AceAndRetailFlags()
    {
        Assert.True(PartsFidelity.Ace.SameBlockGuard);
        Assert.True(PartsFidelity.Ace.EveryPartAnchors);
        Assert.False(PartsFidelity.Retail.SameBlockGuard);
        Assert.False(PartsFidelity.Retail.EveryPartAnchors);
    }

    [FixedSeedProperty(0x9A47_0003, DisplayName = "facts §3.4: adding a part whose extent is non-finite on any one side (x, y, min or max) changes no query's cells")]
    public Property PartsAddAllOutsideCells_NonFinitePartNamesNoCell() =>
        Prop.ForAll(Gen.Zip(PartsGens.Cases, Gen.Zip(Gen.Choose(0, 5), Gen.Choose(0, 8))).ToArbitrary(), t =>
        {
            var (c, (side, at)) = t;
            var anchor = c.Parts[0];
            var o = anchor.Frame.Origin;

            // One non-finite side at a time, the others small: NaN x or y (a disc), or a box whose far corner
            // overflows on one side only (so a broken guard adds a bounded, visibly wrong rectangle instead of hanging).
            var bad = side switch
            {
                0 => Disc(anchor.Cell, new Vector3(float.NaN, o.Y, 0f), 1f),
                1 => Disc(anchor.Cell, new Vector3(o.X, float.NaN, 0f), 1f),
                2 => Slab(anchor.Cell, new Vector3(3e38f, o.Y, 0f), new Vector3(0f, 0f, 0f), new Vector3(1e38f, 1f, 1f)),   // max.x = +inf
                3 => Slab(anchor.Cell, new Vector3(-3e38f, o.Y, 0f), new Vector3(-1e38f, 0f, 0f), new Vector3(0f, 1f, 1f)), // min.x = -inf
                4 => Slab(anchor.Cell, new Vector3(o.X, 3e38f, 0f), new Vector3(0f, 0f, 0f), new Vector3(1f, 1e38f, 1f)),   // max.y = +inf
                _ => Slab(anchor.Cell, new Vector3(o.X, -3e38f, 0f), new Vector3(0f, -1e38f, 0f), new Vector3(1f, 0f, 1f)), // min.y = -inf
            };
            int index = 1 + (at % c.Parts.Count);
            Part[] with = [.. c.Parts.Take(index), bad, .. c.Parts.Skip(index)];

            var plain = new CellArray();
            OutdoorParts.AddAllOutsideCells(plain, c.Parts.ToArray(), anchor.Cell, OpenLand.Instance);
            var extended = new CellArray();
            OutdoorParts.AddAllOutsideCells(extended, with, anchor.Cell, OpenLand.Instance);
            return extended.ToIdArray().SequenceEqual(plain.ToIdArray())
                .Classify(side < 2, "NaN coordinate")
                .Classify(side >= 2, "one infinite side")
                .Classify(index == with.Length - 1, "non-finite part last");
        });

    [FixedSeedProperty(0x9A47_0002, DisplayName = "facts §5.8: Frame.LocalToGlobal is origin + R·p and GlobalToLocal is its inverse Rᵀ·(p − origin)")]
    public Property Frame_TransformsAreOriginPlusRotationAndInverse() =>
        Prop.ForAll(Gen.Zip(Gen.Zip(Coord, Coord, (a, b) => new Vector3(a, b, 5f)), Gen.Zip(Gen.Choose(0, 359), Gen.Zip(Coord, Coord))).ToArbitrary(), t =>
        {
            var (origin, (degrees, (px, py))) = t;
            var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, degrees * MathF.PI / 180f);
            var frame = new Frame(origin, rotation);
            var p = new Vector3(px, py, 1f);
            var global = frame.LocalToGlobal(p);
            var expected = origin + Vector3.Transform(p, rotation);
            var back = frame.GlobalToLocal(global);
            float rad = degrees * MathF.PI / 180f;
            var unitX = frame.LocalToGlobal(Vector3.UnitX) - origin; // a z-rotation by θ maps x̂ to (cos θ, sin θ, 0)
            return Vector3.Distance(global, expected) < 1e-3f && Vector3.Distance(back, p) < 1e-3f
                && Vector3.Distance(frame.GlobalToLocal(origin), Vector3.Zero) < 1e-3f
                && Vector3.Distance(unitX, new Vector3(MathF.Cos(rad), MathF.Sin(rad), 0f)) < 1e-4f;
        });

    private static Gen<float> Coord { get; } = Gen.Choose(1, 190_000).Select(i => i / 1000f);

    private static Part Box(CellId cell, Vector3 origin, float half) =>
        new(cell, new Frame(origin, Quaternion.Identity), new Box(new Vector3(-half, -half, 0f), new Vector3(half, half, 2f)), half, false);

    private static Part Slab(CellId cell, Vector3 origin, Vector3 min, Vector3 max) =>
        new(cell, new Frame(origin, Quaternion.Identity), new Box(min, max), 1f, false);

    private static Part Disc(CellId cell, Vector3 origin, float r) =>
        new(cell, new Frame(origin, Quaternion.Identity), new Box(Vector3.Zero, Vector3.Zero), r, true);
}
