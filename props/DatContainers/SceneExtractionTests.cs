using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Dat;
using AcPhys.Formats.Dat.Container;
using AcPhys.Formats.Scenes;
using AcPhys.Props.Dat;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;
using Xunit.Abstractions;

namespace AcPhys.Props.DatContainers;

/// <summary>
/// DAT-SCENE-EXTRACT: the scene extracted from a dat world at a scene's first block is the scene written into it (its
/// record normal form), and judged the same: the corpus scene walks all in one world, generated scenes one per world.
/// </summary>
public sealed class SceneExtractionTests(ITestOutputHelper output)
{
    public static TheoryData<string> CorpusNames => new(DatTestSupport.CorpusSceneWalks.Select(e => e.Name));

    private static readonly Lazy<(byte[] Cell, byte[] Portal)> CorpusWorld = new(() =>
    {
        var (cell, portal) = SceneContainers.Records(DatTestSupport.CorpusSceneWalks.Select(e => e.Entry.SceneWalk!.Scene));
        return (DatContainerWriter.ToBytes(cell, DatSet.Cell, 1024), DatContainerWriter.ToBytes(portal, DatSet.Portal, 256));
    });

    [Theory(DisplayName = "DAT-SCENE-EXTRACT: a corpus scene walk extracted from the world of all corpus scenes is the same scene, with the same verdicts (reference holds, every named fault caught by the same invariant)")]
    [MemberData(nameof(CorpusNames))]
    public void CorpusSceneComesBack(string name)
    {
        var entry = DatTestSupport.CorpusSceneWalks.Single(e => e.Name == name).Entry;
        var sw = entry.SceneWalk!;
        using var world = Open(CorpusWorld.Value);
        var got = SceneExtraction.Extract(world, new ScenePlace(sw.Scene.Blocks[0]));
        output.WriteLine(got.Report.ToString());
        Same(DatNormalForm.Of(sw.Scene), got.Scene);
        Assert.Equal(sw.Scene.Cells.Count, got.Report.KeptCells);

        var back = new SceneWalk(got.Scene, sw.Walk);
        Assert.Null(InvariantCatalogue.CheckSceneWalk(ReferenceAdapter.Instance, back));
        foreach (string fault in entry.Catches)
        {
            var before = InvariantCatalogue.CheckSceneWalk(PlantedFaults.Create(fault), sw);
            var after = InvariantCatalogue.CheckSceneWalk(PlantedFaults.Create(fault), back);
            Assert.Equal(before?.InvariantId, after?.InvariantId);
            Assert.NotNull(after);
        }
    }

    [Fact(DisplayName = "DAT-SCENE-EXTRACT: 150 generated scene walks (cottages, dungeons), each written as a dat world, come back as their normal form from their cells' block, the reference holding on both")]
    public void GeneratedScenesComeBack()
    {
        int same = 0, outside = 0, undeclared = 0;
        foreach (var sw in Gen.Sample(SceneGens.Recipes.Select(r => r.Build()), 150, new Rnd(43, 0x9E3779B97F4A7C15UL), 50))
        {
            // Extraction declares the chosen block's 3 × 3 neighbourhood (unloaded where the file has no Landblock). A
            // scene that leaves a neighbour undeclared means the same (any block not loaded is unloaded), so it is
            // compared with its neighbours declared; a scene declaring blocks beyond the neighbourhood is counted apart.
            var scene = sw.Scene;
            var b0 = scene.Cells.Count > 0 ? scene.Cells[0].Id.Landblock : scene.Blocks[0];
            var hood = Enumerable.Range(-1, 3).SelectMany(dx => Enumerable.Range(-1, 3).Select(dy => (X: b0.X + dx, Y: b0.Y + dy)))
                .Where(p => p.X is >= 0 and <= 0xFE && p.Y is >= 0 and <= 0xFE).Select(p => new LandblockId((byte)p.X, (byte)p.Y)).ToHashSet();
            if (!scene.Blocks.Concat(scene.UnloadedBlocks).All(hood.Contains) || scene.Cells.Any(c => c.Id.Landblock != b0))
            {
                outside++;
                continue;
            }

            undeclared += scene.Blocks.Count + scene.UnloadedBlocks.Count < hood.Count ? 1 : 0;
            var (cell, portal) = SceneContainers.Records([scene]);
            using var world = Open((DatContainerWriter.ToBytes(cell, DatSet.Cell, 256), DatContainerWriter.ToBytes(portal, DatSet.Portal, 1024)));
            var got = SceneExtraction.Extract(world, new ScenePlace(b0));
            // An unloaded cell nothing names (no portal, door or visible list) has no record in the file and no effect
            // on a query (load hints come from portals): the extraction cannot see it, so it is not expected back.
            var named = scene.Cells.SelectMany(c => c.Portals.Where(p => !p.IsExit).Select(p => c.Id.WithLow(p.Other)).Concat(c.Visible))
                .Concat(scene.Buildings.SelectMany(b => b.Portals.Select(p => new CellId(b.Block.X, b.Block.Y, p.Cell)))).ToHashSet();
            var expected = DatNormalForm.Of(scene) with { UnloadedBlocks = [.. hood.Except(scene.Blocks)], UnloadedCells = [.. scene.UnloadedCells.Where(named.Contains)] };
            Same(Sorted(expected), Sorted(got.Scene));
            Assert.Null(InvariantCatalogue.CheckSceneWalk(ReferenceAdapter.Instance, new SceneWalk(got.Scene, sw.Walk)));
            same++;
        }

        output.WriteLine($"{same} compared ({undeclared} of them with neighbours the scene left undeclared), {outside} have cells in two blocks or declare blocks beyond the neighbourhood of the first cell's block");
        Assert.True(same >= 120, $"only {same} of 150 generated scenes compared ({outside} with cells in two blocks or blocks beyond the neighbourhood)");
    }

    [Fact(DisplayName = "DAT-SCENE-EXTRACT: a place with a point keeps the cells near it and through their portals; doors elsewhere become load hints")]
    public void AroundAPoint()
    {
        var sw = DatTestSupport.CorpusSceneWalks.Single(e => e.Name == "scene-land-to-second-room.json").Entry.SceneWalk!;
        using var world = Open(CorpusWorld.Value);
        var second = sw.Scene.Cells[1];
        var got = SceneExtraction.Extract(world, new ScenePlace(sw.Scene.Blocks[0], second.Origin.X, second.Origin.Y, 0.5f));
        output.WriteLine(got.Report.ToString());
        Assert.Equal(2, got.Report.KeptCells);
        Assert.True(got.Report.Kept.GetValueOrDefault(KeepReason.Near) >= 1, got.Report.ToString());

        var far = SceneExtraction.Extract(world, new ScenePlace(sw.Scene.Blocks[0], 0, 0, 1));
        Assert.Equal(0, far.Report.KeptCells);
        Assert.Equal([sw.Scene.Cells[0].Id], far.Scene.UnloadedCells);
        Assert.Equal(1, far.Report.Hints[HintReason.Unreached]);
    }

    [Fact(DisplayName = "DAT-SCENE-EXTRACT: --max-cells cuts a dungeon: the rest become load hints and the scene is still valid")]
    public void MaxCellsCuts()
    {
        var dungeon = SceneKit.Dungeon(new DungeonPlan((192.0 * 0x20) + 150, (192.0 * 0x21) + 30, 6, 8, 1, 0x33));
        var (cell, portal) = SceneContainers.Records([dungeon]);
        using var world = Open((DatContainerWriter.ToBytes(cell, DatSet.Cell, 256), DatContainerWriter.ToBytes(portal, DatSet.Portal, 256)));
        var block = dungeon.Cells[0].Id.Landblock;
        var all = SceneExtraction.Extract(world, new ScenePlace(block));
        var cut = SceneExtraction.Extract(world, new ScenePlace(block), maxCells: 2);
        output.WriteLine(all.Report + "\n" + cut.Report);
        Assert.Equal(2, cut.Report.KeptCells);
        Assert.Equal(all.Report.KeptCells - 2, cut.Report.Hints.GetValueOrDefault(HintReason.Cut));
        Assert.Equal(2, cut.Scene.Cells.Count);
    }

    [Fact(DisplayName = "DAT-SCENE-EXTRACT: a record the record reader refuses inside a container is a DatContainerException naming that object")]
    public void RefusedRecordNamesTheObject()
    {
        var sw = DatTestSupport.CorpusSceneWalks[0].Entry.SceneWalk!;
        var (cell, portal) = SceneContainers.Records([sw.Scene]);
        uint victim = cell.First(c => RecordIds.TypeOf(c.Id, false) == RecordType.EnvCell).Id;
        cell = [.. cell.Select(c => c.Id == victim ? (c.Id, c.Bytes[..^1]) : c)];
        using var world = Open((DatContainerWriter.ToBytes(cell, DatSet.Cell, 256), DatContainerWriter.ToBytes(portal, DatSet.Portal, 256)));
        var e = Assert.Throws<DatContainerException>(() => SceneExtraction.Extract(world, new ScenePlace(sw.Scene.Blocks[0])));
        Assert.Equal(victim, e.ObjectId);
        Assert.True(e.Offset > 0);
        Assert.Contains("record reader refuses", e.Message);
    }

    /// <summary>The record round trip's equality (props/Dat): no difference at tolerance 0, the same text but for the sign of zeros (dat-scenes.md "Round-trip normal form").</summary>
    private static void Same(Scene expected, Scene actual)
    {
        var diff = DatNormalForm.Differences(expected, actual, 0);
        Assert.True(diff.Count == 0, $"{string.Join("; ", diff)}: expected {expected} unloaded cells [{string.Join(", ", expected.UnloadedCells)}], got {actual} unloaded cells [{string.Join(", ", actual.UnloadedCells)}]");
        Assert.Equal(Unsigned(SceneJson.Write(expected)), Unsigned(SceneJson.Write(actual)));
    }

    private static string Unsigned(string json) => System.Text.RegularExpressions.Regex.Replace(json, @"-0(?![\d.eE])", "0");

    private static DatWorld Open((byte[] Cell, byte[] Portal) bytes) =>
        new(DatContainer.Open(new MemoryBlockSource(bytes.Cell, "cell.dat")), DatContainer.Open(new MemoryBlockSource(bytes.Portal, "portal.dat")));

    private static Scene Sorted(Scene s) => s with { Blocks = [.. s.Blocks.OrderBy(b => b.Value)], UnloadedBlocks = [.. s.UnloadedBlocks.OrderBy(b => b.Value)], Cells = [.. s.Cells.OrderBy(c => c.Id.Value)], UnloadedCells = [.. s.UnloadedCells.OrderBy(c => c.Value)] };
}
