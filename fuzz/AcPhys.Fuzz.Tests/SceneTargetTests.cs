using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Fuzz.Targets;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using Xunit;

namespace AcPhys.Fuzz.Tests;

/// <summary>The <c>scene</c> target: its codec, its checks under indoor faults, and the triage of its crashes.</summary>
public sealed class SceneTargetTests
{
    // corpus/fuzz/scene/<name>: the bytes that decode to corpus/seeds/<file>.
    private static readonly (string Seed, string Case)[] CottageSeeds =
    [
        ("f4eb60618e8e65a8", "cottage-a9b3-a9b4-through.json"),
        ("17cc54d7516288c1", "cottage-a9b3-a9b4-in-and-out.json"),
    ];

    private static readonly SceneWalkTarget Target = (SceneWalkTarget)FuzzTargets.Find("scene")!;

    [Fact]
    public void Any_bytes_decode_to_a_bounded_scene_walk_that_holds_on_the_correct_core()
    {
        // Every input reaches the physics: random, empty, all-ones and a megabyte decode without an exception, stay
        // bounded, and break no indoor invariant on the reference.
        var inputs = CodecInputs.Edges(SceneCodec.Length, 150, seed: 11);

        foreach (var input in inputs)
        {
            var sw = Target.Decode(input);
            Assert.NotNull(sw.Recipe);
            Assert.InRange(sw.Scene.Cells.Count + sw.Scene.UnloadedCells.Count, 1, 5);
            Assert.InRange(sw.Walk.Steps.Count, 0, SceneCodec.MaxSteps);
            Assert.Null(Target.Classify(input, fault: null));
        }
    }

    [Theory]
    [InlineData("ff53c8fefffb7f35b737154000f158fb2c")]
    [InlineData("000701ffff97fa00011200ffec97fa00011200fc1c22f5fa")]
    public void A_line_jitter_beside_a_yawed_cottage_stays_outdoors(string hex)
    {
        // Found by a correct-core campaign: a quarter-turned cottage whose wall lay on the nearest 24 m line, so the
        // LineJitter walk started in the room and stepped out through the wall (NEVER-NULL, PORTAL-TRANSIT on the
        // reference). The recipe now takes the nearest line clear of the footprint; the inputs hold.
        byte[] input = Convert.FromHexString(hex);
        var sw = Target.Decode(input);

        Assert.Equal(SceneRoute.LineJitter, sw.Recipe!.Route);
        Assert.Null(Target.Classify(input, fault: null));
    }

    [Fact]
    public void A_walk_onto_an_unloaded_neighbour_block_is_built_with_the_neighbours_loaded()
    {
        // Found by a correct-core campaign: a yawed cottage 1 m short of its block's north line, neighbours unloaded,
        // walked in and back out: the centre left the room onto the unloaded block and the body was lost
        // (PORTAL-TRANSIT, NEVER-NULL on the reference). A client always has its neighbour blocks loaded.
        byte[] input = Convert.FromHexString("00fa0000fa6e7474747474000000730000");
        var sw = Target.Decode(input);

        Assert.True(((SceneRecipe)sw.Recipe!).Cottage!.LoadNeighbours);
        Assert.Empty(sw.Scene.UnloadedBlocks);
        Assert.Null(Target.Classify(input, fault: null));
        var inBlock = new byte[SceneCodec.Length];
        inBlock[8] = 4; // neighbours unloaded
        inBlock[13] = 100; // 100 m into the block: the walk stays in it
        Assert.Equal(8, Target.Decode(inBlock).Scene.UnloadedBlocks.Count); // the flag still works
    }

    [Theory]
    [InlineData("3a3a3a3a3a3a3a353a3f3a3a3a3a803a3a3a3a3a3a3a3a00e60197a59707ff00640006")]
    [InlineData("c17f190010c1feef64ffe4800000c8c86565656565656565")]
    public void A_walk_stops_before_it_leaves_the_map(string hex)
    {
        // Found by a correct-core campaign: a cottage at the west map edge, yawed so its rooms overhang the edge,
        // walked through and out of its back door onto no land; back on the map the body was lost (NEVER-NULL,
        // PORTAL-TRANSIT on the reference). The walk now ends before its centre would leave the map.
        byte[] input = Convert.FromHexString(hex);
        var sw = Target.Decode(input);

        Assert.Equal(0, ((SceneRecipe)sw.Recipe!).Cottage!.Block.X);
        Assert.True(sw.Walk.Steps.Count < ((SceneRecipe)sw.Recipe).Take, $"not cut: {sw.Walk.Steps.Count} steps");
        Assert.Null(Target.Classify(input, fault: null));
    }

    [Fact]
    public void The_scene_seed_corpus_decodes_to_the_cottage_corpus_cases()
    {
        foreach (var (seed, file) in CottageSeeds)
        {
            var stored = CorpusJson.ReadFile(Path.Combine(RepoPaths.Root, "corpus", "seeds", file));
            var decoded = Target.Decode(File.ReadAllBytes(Path.Combine(RepoPaths.Root, "corpus", "fuzz", "scene", seed)));

            Assert.Equal(CorpusJson.Write(stored), CorpusJson.Write(stored with { SceneWalk = decoded with { Recipe = null } }));
        }
    }

    [Theory]
    [InlineData("no-exit-transit")]
    [InlineData("outdoor-wins")]
    public void The_cottage_walk_breaks_the_invariant_that_catches_the_fault(string fault)
    {
        // The through-walk of corpus/seeds exposes these faults; the test throws the typed violation with the ID
        // the catalogue reports first, one of the invariants the fault is documented to break.
        byte[] input = File.ReadAllBytes(Path.Combine(RepoPaths.Root, "corpus", "fuzz", "scene", CottageSeeds[0].Seed));
        var expected = InvariantCatalogue.CheckSceneWalk(PlantedFaults.Create(fault), Target.Decode(input));
        Assert.NotNull(expected);
        Assert.Contains(expected.InvariantId, PlantedFaults.Find(fault)!.CaughtBy);

        var thrown = Assert.Throws<InvariantViolationException>(() => Target.CreateTest(fault)(input));

        Assert.Equal(expected.InvariantId, thrown.Violation.InvariantId);
        Assert.Equal(expected.InvariantId, Target.Classify(input, fault)!.Key);
        Target.CreateTest(fault: null)(input); // the correct core passes the same input
    }

    [Fact]
    public void A_scene_crash_is_shrunk_to_a_scene_walk_regression_that_replays()
    {
        const string fault = "no-exit-transit";
        byte[] input = File.ReadAllBytes(Path.Combine(RepoPaths.Root, "corpus", "fuzz", "scene", CottageSeeds[0].Seed));
        var finding = Target.Classify(input, fault)!;
        var original = (SceneWalk)finding.Case!.Value;

        var entry = Target.Minimise(finding, fault, "test")!;
        string path = Path.Combine(Path.GetTempPath(), $"acphys-scene-{Environment.ProcessId}-{FailureFile.NameFor(entry)}");
        AtomicFile.WriteAllText(path, CorpusJson.Write(entry));
        var read = CorpusJson.ReadFile(path);
        File.Delete(path);

        Assert.Equal("scene-walk", read.Kind);
        Assert.Equal(finding.Key, read.Invariant);
        Assert.Equal([fault], read.Catches);
        Assert.Equal(finding.Key, InvariantCatalogue.CheckEntry(PlantedFaults.Create(fault), read)?.InvariantId);
        Assert.Null(InvariantCatalogue.CheckEntry(ReferenceAdapter.Instance, read));
        Assert.True(read.SceneWalk!.Walk.Steps.Count < original.Walk.Steps.Count, $"not shrunk: {read.SceneWalk.Size} vs {original.Size}");
        Assert.Equal(FailureFile.NameFor(entry), FailureFile.NameFor(Target.Minimise(finding, fault, "again")!)); // same file
    }
}
