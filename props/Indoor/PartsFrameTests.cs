using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>
/// The parts a scene walk stands for are varied enough to tell a port's frame and box bugs apart (issue 41, "frames"):
/// their shapes keep the sphere-gate bound the remarks state, a part framed across a block line keeps its world
/// position, and each class of the parts queries is hit on the pr cases.
/// </summary>
public sealed class PartsFrameTests(ITestOutputHelper output)
{
    private static readonly string[] PartsClasses =
    [
        ScenePartsClasses.Rotated3D, ScenePartsClasses.OffCentre, ScenePartsClasses.OtherBlock, ScenePartsClasses.BoxBesideDoor,
        ScenePartsClasses.PokingBox, ScenePartsClasses.FlatBox, ScenePartsClasses.LongBox, ScenePartsClasses.TidyBox, ScenePartsClasses.SphereAcrossBoxNot,
        ScenePartsClasses.BoxAcrossGateShut, ScenePartsClasses.BoxAcrossGateOpen, ScenePartsClasses.AnchorMissingEnv, ScenePartsClasses.AnchorBlockId, ScenePartsClasses.AnchorBlockEdge,
    ];

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS (shapes): boxes are retail-like — each holds its origin off-centre within [−r, r]³ with unequal sides; per part over every 8 steps 4 tidy (corners ≤ 0.48·r), 2 poking (0.86·r to 1.65·r), 1 flat (0.07·r thick), 1 long (1.9·r); hulls within √3·1.65·r")]
    public void BoxesAreRetailLike()
    {
        var counts = new Dictionary<PartShape, int>();
        float pokingLo = float.MaxValue, pokingHi = 0;
        for (int step = 0; step < 400; step++)
        {
            for (int k = 0; k < 5; k++)
            {
                var kind = PartShapes.Kind(step, k);
                counts[kind] = counts.GetValueOrDefault(kind) + 1;
                var box = PartShapes.Bounds(step, k, 1f);
                var size = box.Max - box.Min;
                Assert.NotEqual(Vector3.Zero, box.Min + box.Max);
                Assert.True(size.X != size.Y && size.Y != size.Z, "sides differ per axis");
                Assert.True(Vector3.Max(box.Min, Vector3.Zero) == Vector3.Zero && Vector3.Min(box.Max, Vector3.Zero) == Vector3.Zero, $"step {step} part {k}: {box} does not hold the origin");
                Assert.True(Vector3.Min(box.Min, new Vector3(-1)) == new Vector3(-1) && Vector3.Max(box.Max, Vector3.One) == Vector3.One, $"step {step} part {k}: {box} leaves [−r, r]³");
                float far = Enumerable.Range(0, 8).Max(c => box.Corner(c).Length());
                float thin = MathF.Min(size.X, MathF.Min(size.Y, size.Z)), longest = MathF.Max(size.X, MathF.Max(size.Y, size.Z));
                switch (kind)
                {
                    case PartShape.Tidy:
                        Assert.True(far <= 0.48f, $"tidy corner {far}");
                        break;
                    case PartShape.Poking:
                        pokingLo = MathF.Min(pokingLo, far);
                        pokingHi = MathF.Max(pokingHi, far);
                        break;
                    case PartShape.Flat:
                        Assert.Equal(0.07f, thin, 3);
                        break;
                    default:
                        Assert.Equal(1.9f, longest, 3);
                        break;
                }

                // The hull in a frame turned by the part's rotation and then by any cell's yaw stays within √3·Reach.
                var part = new Part(new CellId(0x12340001), new Frame(Vector3.Zero, PartShapes.Rotation(step, k)), box, 1f, false);
                var hull = BoxSide.InFrame(part, part.Cell, new Frame(Vector3.Zero, Quaternion.CreateFromAxisAngle(Vector3.UnitZ, step * 0.1f)));
                for (int c = 0; c < 8; c++)
                {
                    Assert.True(hull.Corner(c).Length() <= MathF.Sqrt(3) * PartShapes.Reach, $"step {step} part {k}: hull corner {hull.Corner(c)} beyond √3·Reach");
                }
            }
        }

        output.WriteLine($"kinds over 400 steps × 5 parts: {string.Join(", ", counts.Select(kv => $"{kv.Key} {kv.Value}"))}; poking corners {pokingLo:F3}·r to {pokingHi:F3}·r");
        Assert.Equal(1000, counts[PartShape.Tidy]);
        Assert.Equal(500, counts[PartShape.Poking]);
        Assert.Equal(250, counts[PartShape.Flat]);
        Assert.Equal(250, counts[PartShape.Long]);
        Assert.InRange(pokingLo, 0.8f, 1f);
        Assert.InRange(pokingHi, 1.5f, PartShapes.Reach);
        Assert.True(PartShapes.Reach < MathF.Sqrt(3));
    }

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS (shapes): odd steps pitch and roll every part (its heading-only rotation turns a vector differently), even steps only yaw it")]
    public void OddStepsAreTilted()
    {
        for (int step = 0; step < 200; step++)
        {
            for (int k = 0; k < 4; k++)
            {
                var q = PartShapes.Rotation(step, k);
                var up = Vector3.Transform(Vector3.UnitZ, q);
                Assert.Equal(PartShapes.Tilted(step), up.Z < 0.99f);
                var v = new Vector3(0.3f, -0.5f, 0.8f);
                float moved = Vector3.Distance(Vector3.Transform(v, q), Vector3.Transform(v, PartShapes.Heading(q)));
                Assert.True(PartShapes.Tilted(step) ? moved > 0.1f : moved < 1e-4f, $"step {step} part {k}: the heading-only rotation moves a vector by {moved}");
                Assert.True(MathF.Abs(q.Length() - 1) < 1e-5f);
            }
        }
    }

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS (frames): a part framed across a block line is a land cell of the adjacent block on the map, and its world position is the sphere's")]
    public void AcrossLineKeepsTheWorldPosition()
    {
        int across = 0;
        foreach (uint block in new uint[] { 0x0000, 0x0001, 0xA9B4, 0xFEFE, 0x00FE })
        {
            var cell = new CellId((block << 16) | 0x0100);
            for (float x = -3; x <= 195; x += 1.7f)
            {
                for (float y = -3; y <= 195; y += 2.3f)
                {
                    var p = new Vector3(x, y, 1.5f);
                    if (PartFrames.AcrossLine(cell, p) is not { } a)
                    {
                        continue;
                    }

                    across++;
                    Assert.True(a.Cell.IsLand, $"{a.Cell} is not a land cell");
                    Assert.Equal(1, Math.Abs(a.Cell.BlockX - cell.BlockX) + Math.Abs(a.Cell.BlockY - cell.BlockY));
                    double wx = (192.0 * a.Cell.BlockX) + a.Origin.X, wy = (192.0 * a.Cell.BlockY) + a.Origin.Y;
                    Assert.Equal((192.0 * cell.BlockX) + x, wx, 3);
                    Assert.Equal((192.0 * cell.BlockY) + y, wy, 3);
                    Assert.Equal(p.Z, a.Origin.Z);
                }
            }
        }

        output.WriteLine($"{across} points framed across a line");
        Assert.True(across > 1000);
    }

    [Fact(DisplayName = "PARTS-INDOOR-COVERAGE (classes): the pr cases hit every parts class — rotated-3d, off-centre-box, other-block-frame, box-beside-door, the box shapes, the gate and box disagreements and the anchor kinds (distribution printed)")]
    public void EveryPartsClassIsHit()
    {
        var judge = PartsIndoorInvariants.Coverage;
        var counts = PartsClasses.ToDictionary(c => c, _ => 0);
        int cases = 0;
        CaseSweep.Each(judge.Domain, Profile.Pr.CasesPerInvariant, Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), c =>
        {
            cases++;
            foreach (var tag in judge.Domain.Classes(c).Where(counts.ContainsKey))
            {
                counts[tag]++;
            }

            return true;
        });
        output.WriteLine($"{cases} pr cases of {judge.Id}: " + string.Join(", ", counts.Select(kv => $"{kv.Key} {kv.Value}")));
        Assert.All(counts, kv => Assert.True(kv.Value >= 20, $"{kv.Key}: {kv.Value} hits"));
    }

    [Fact(DisplayName = "PARTS-BUILDING-ENTRY (§7 #14, measured): on the pr cases of box-beside-door, ACE's box-side pairing and retail's answer a door check differently, and on some a cell enters one list only")]
    public void BoxSidePairingIsToldApart()
    {
        var judge = PartsIndoorInvariants.BuildingEntry;
        int ofClass = 0, doorsDiffer = 0, listsDiffer = 0;
        CaseSweep.Each(judge.Domain, Profile.Pr.CasesPerInvariant, Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), c =>
        {
            if (!judge.Domain.Classes(c).Contains(ScenePartsClasses.BoxBesideDoor))
            {
                return true;
            }

            ofClass++;
            var (door, list) = Pairings(c);
            doorsDiffer += door ? 1 : 0;
            listsDiffer += list ? 1 : 0;
            return true;
        });
        output.WriteLine($"{ofClass} pr cases of {ScenePartsClasses.BoxBesideDoor}; a door check answered differently by the two pairings on {doorsDiffer}; a cell enters one list only on {listsDiffer}");
        Assert.True(doorsDiffer > 0, "the box-side pairing never decides a door check on the pr cases");
        Assert.True(listsDiffer > 0, "the box-side pairing never changes a list on the pr cases");
    }

    // Per door of a listed loaded land cell: CheckBuildingTransit with retail's and ACE's pairing on fresh arrays. A list
    // differs when ACE enters a cell retail's list lacks, or retail alone enters a cell that has no other way in (not the
    // anchor's, and no other listed env cell has a portal to it).
    private static (bool Door, bool List) Pairings(SceneWalk w)
    {
        var scene = SceneBuild.Build(w.Scene);
        bool door = false, list = false;
        foreach (var (_, parts) in ScenePartsQueries.Of(w))
        {
            var listed = ReferenceAdapter.Instance.FindCellParts(w.Scene, parts, true).Cells;
            foreach (var land in listed.Where(id => id.IsLand && scene.IsLoaded(id.Landblock)))
            {
                if (scene.GetBuilding(land) is not { } building)
                {
                    continue;
                }

                foreach (var d in building.Portals)
                {
                    if (scene.GetEnvCell(land.WithLow(d.OtherCellId)) is not { } cell)
                    {
                        continue;
                    }

                    bool retail = EnvTransitParts.CheckBuildingTransit(new CellArray(), scene, cell, d.OtherPortalId, parts, IndoorFidelity.Retail);
                    bool ace = EnvTransitParts.CheckBuildingTransit(new CellArray(), scene, cell, d.OtherPortalId, parts, IndoorFidelity.Retail with { AceBoxSidePairing = true });
                    if (retail != ace)
                    {
                        door = true;
                        list |= (ace && !listed.Contains(cell.Id)) || (retail && !OtherWayIn(scene, listed, cell.Id, parts[0].Cell));
                    }
                }
            }
        }

        return (door, list);
    }

    private static bool OtherWayIn(CellScene scene, IReadOnlyList<CellId> listed, CellId cell, CellId anchor) =>
        cell == anchor || listed.Any(id => id != cell && id.IsEnv && scene.GetEnvCell(id) is { } e && e.Portals.ToArray().Any(p => id.WithLow(p.OtherCellId) == cell));
}
