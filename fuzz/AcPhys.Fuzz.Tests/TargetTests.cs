using System.Text;
using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Fuzz.Targets;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using Xunit;

namespace AcPhys.Fuzz.Tests;

/// <summary>The fuzz targets and their triage, without afl-fuzz (milliseconds).</summary>
public sealed class TargetTests
{
    public static TheoryData<string> Names
    {
        get
        {
            var data = new TheoryData<string>();
            foreach (var t in FuzzTargets.All)
            {
                data.Add(t.Name);
            }

            return data;
        }
    }

    [Fact]
    public void Registry_finds_every_target_class_once()
    {
        var names = FuzzTargets.All.Select(t => t.Name).ToArray();

        Assert.Equal(["land", "parts", "scene", "walk", "corpus", "dat-container", "dat-records", "scene-json", "serve-request", "walk-json", "toy", "toy-slow"], names);
        Assert.Equal(names.Length, names.Distinct().Count());
    }

    [Theory]
    [MemberData(nameof(Names))]
    public void Every_seed_passes_on_the_correct_core(string name)
    {
        var target = FuzzTargets.Find(name)!;

        Assert.NotEmpty(target.Seeds);
        Assert.All(target.Seeds, s => Assert.Null(target.Classify(s.Value, fault: null)));
    }

    [Theory]
    [InlineData("land")]
    [InlineData("walk")]
    [InlineData("scene")]
    [InlineData("parts")]
    public void Physics_targets_reach_the_physics_on_any_bytes(string name)
    {
        // No input may stop in a parser: random bytes decode and are checked, and none fails on the correct core.
        var target = FuzzTargets.Find(name)!;
        var random = new Random(7);
        for (int i = 0; i < 300; i++)
        {
            var input = new byte[random.Next(0, 64)];
            random.NextBytes(input);
            Assert.Null(target.Classify(input, fault: null));
        }
    }

    [Fact]
    public void A_walk_crash_under_a_fault_is_shrunk_to_a_regression_that_separates_fault_and_core()
    {
        var target = (WalkTarget)FuzzTargets.Find("walk")!;
        byte[] crash = [0x31, 0x00, 0x24, 0x3A, 0x00, 0x40, 0x00, 0x40, 0x00, 0x10, 0x05, 0x7F, 0x00, 0x05, 0x10, 0x20];
        var finding = target.Classify(crash, "sticky-pick");
        Assert.NotNull(finding);
        Assert.True(finding.IsViolation);

        var entry = target.Minimise(finding, "sticky-pick", "test")!;

        Assert.Equal(finding.Key, entry.Invariant);
        Assert.Equal(["sticky-pick"], entry.Catches);
        Assert.Equal(finding.Key, InvariantCatalogue.CheckEntry(PlantedFaults.Create("sticky-pick"), entry)?.InvariantId);
        Assert.Null(InvariantCatalogue.CheckEntry(ReferenceAdapter.Instance, entry));
        var original = (Walk)finding.Case!.Value;
        Assert.True(entry.Walk!.Steps.Count <= original.Steps.Count && entry.Walk.Body.Count <= original.Body.Count);
        Assert.Equal(FailureFile.NameFor(entry), FailureFile.NameFor(target.Minimise(finding, "sticky-pick", "again")!)); // deterministic: same file
    }

    [Fact]
    public void A_land_crash_is_shrunk_toward_round_values()
    {
        var target = (LandTarget)FuzzTargets.Find("land")!;
        byte[] input = LandCaseCodec.Encode(new LandCase(new AcPhys.Core.CellId(0x12340001), -0.73125f, 100.123f, new AcPhys.Core.Lcoord(3, 5)));
        var finding = target.Classify(input, "trunc-floor")!;

        var entry = target.Minimise(finding, "trunc-floor", "test")!;

        Assert.Equal(finding.Key, entry.Invariant);
        Assert.True(entry.Case!.Value.Y is 0f, $"y not shrunk: {entry.Case}");
        Assert.NotNull(InvariantCatalogue.CheckLandCase(PlantedFaults.Create("trunc-floor"), entry.Case.Value));
    }

    [Theory]
    [InlineData("corpus")]
    [InlineData("walk-json")]
    public void Parser_targets_reject_garbage_cleanly_and_round_trip_what_they_accept(string name)
    {
        var test = FuzzTargets.Find(name)!.CreateTest(fault: null);
        string[] inputs = ["", "{", "null", "[1,2]", "{\"format\":\"acphys-case\",\"version\":1}", "{\"start\":{\"cell\":\"0x00000001\"}}", "\u00ff\u00fe"];

        foreach (string s in inputs)
        {
            test(Encoding.UTF8.GetBytes(s)); // returns: only InputFormatException (swallowed) was thrown
        }
    }

    [Fact]
    public void Parser_targets_take_no_fault_and_physics_targets_reject_an_unknown_one()
    {
        Assert.Throws<ArgumentException>(() => FuzzTargets.Find("corpus")!.CreateTest("trunc-floor"));
        Assert.Throws<ArgumentException>(() => FuzzTargets.Find("walk")!.CreateTest("no-such-fault"));
    }

    [Fact]
    public void Signatures_mask_numbers_ids_and_lists()
    {
        Assert.Equal(
            Signatures.Of("step 3: from block 0x3925: [0x3A240004, 0x3A240005] vs [0x3A240003] at -1.5E-05"),
            Signatures.Of("step 12: from block 0x0001: [0x3A240004] vs [] at NaN"));
    }
}
