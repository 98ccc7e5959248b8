using AcPhys.Cli.Diff;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Running;

namespace AcPhys.E2E;

/// <summary>
/// DIFF-CLASSES: acphys diff counts every diverging input in one divergence class per root cause, keeps one shrunk
/// example per class, and its counts are the real number of differing inputs (checked in process, against a recount).
/// </summary>
public sealed class DiffClassTests
{
    private static readonly Seed Fixed = Seed.Derive(0xD1FF, "diff-class-tests");

    [Fact]
    public void TheReferenceAgainstItselfHasNoDivergence()
    {
        var reference = new ReferenceAdapter(PickPolicy.Retail);
        foreach (var check in new DiffChecks(new ReferenceAdapter(PickPolicy.Retail)).All)
        {
            var r = check.Run(reference, 300, Fixed);
            Assert.True(r.Divergent == 0 && r.Classes.Count == 0, $"{check.Id}: {string.Join("; ", r.Classes.Select(c => c.What + " " + c.Message))}");
            Assert.Equal(300, r.Cases);
        }
    }

    [Fact]
    public void TwoBugsInOnePortAreTwoClassesWithTheirCounts()
    {
        var port = PlantedFaults.Combine("clamp-106", "touch-inclusive");
        var r = Check("DIFF-OUTSIDE-CELLS").Run(port, 1000, Fixed);

        var classes = r.Classes.Select(c => c.What).ToArray();
        Assert.Contains("outside_cells: missing cells (other block)", classes); // the clamp
        Assert.Contains("outside_cells: extra cells", classes);                 // the inclusive edge test
        Assert.Equal(r.Divergent, r.Classes.Sum(c => c.Count));
        Assert.True(r.Classes.Zip(r.Classes.Skip(1)).All(p => p.First.Count >= p.Second.Count), "classes are listed most frequent first");
    }

    [Fact]
    public void TheCountIsEveryDifferingInputNotJustTheFirst()
    {
        var port = PlantedFaults.Combine("clamp-106");
        var reference = new ReferenceAdapter(PickPolicy.Retail);
        var r = Check("DIFF-OUTSIDE-CELLS").Run(port, 1000, Fixed);

        // Recount independently over the same generated inputs: answers compared as plain lists.
        int differing = 0;
        CaseSweep.Each(OutdoorDomain.Instance, 1000, Fixed, q =>
        {
            differing += port.OutsideCells(q.Cell, q.Origin, q.Spheres).SequenceEqual(reference.OutsideCells(q.Cell, q.Origin, q.Spheres)) ? 0 : 1;
            return true;
        });

        Assert.True(differing > 1, "the clamp must show on more than one input for this test to mean anything");
        Assert.Equal(differing, r.Divergent);
        var only = Assert.Single(r.Classes); // one bug, one class
        Assert.Equal("outside_cells: missing cells (other block)", only.What);
    }

    [Fact]
    public void EachClassExampleIsShrunkWithoutLeavingItsClass()
    {
        var port = PlantedFaults.Combine("clamp-106", "touch-inclusive");
        var check = (DiffCheck<Walk>)Check("DIFF-WALK");
        var r = check.Run(port, 500, Fixed);
        Assert.NotEmpty(r.Classes);
        foreach (var c in r.Classes.Where(c => c.Shrunk))
        {
            var walk = Assert.IsType<Walk>(c.Example);
            Assert.Equal(c.What, check.Compare(port, walk)?.What);
        }

        // The clamp's walks shrink to a start on a block corner with no steps at all.
        var clamp = r.Classes.Single(c => c.What == "find_cell along the walk: missing cells (other block)");
        Assert.Empty(Assert.IsType<Walk>(clamp.Example).Steps);
    }

    [Fact]
    public void TheSameSeedGivesTheSameClassesAndCounts()
    {
        var port = PlantedFaults.Combine("clamp-106", "touch-inclusive");
        var a = Check("DIFF-FIND-CELL").Run(port, 400, Fixed);
        var b = Check("DIFF-FIND-CELL").Run(port, 400, Fixed);
        Assert.Equal(a.Classes.Select(c => (c.What, c.Count, c.Example.ToString())), b.Classes.Select(c => (c.What, c.Count, c.Example.ToString())));
    }

    [Fact]
    public void AThrowIsAClassOfItsOwn()
    {
        var port = PlantedFaults.Combine("checked-cast");
        var r = Check("DIFF-OUTSIDE-CELLS").Run(port, 1000, Fixed);
        Assert.Contains(r.Classes, c => c.What.StartsWith("outside_cells: threw ", StringComparison.Ordinal));
    }

    [Fact]
    public void AnOutdoorWinsPortIsOneIndoorClassNamingTheKindsOfCell()
    {
        var port = PlantedFaults.Create("outdoor-wins");
        var r = Check("DIFF-SCENE-WALK").Run(port, 300, Fixed);
        Assert.True(r.Divergent > 0, "the scene walks must reach a building");
        var only = Assert.Single(r.Classes);
        Assert.Equal("static find_cell in a scene: containing a land cell, reference an env cell", only.What);
        Assert.IsType<SceneWalk>(only.Example);
    }

    private static DiffCheck Check(string id) => new DiffChecks(new ReferenceAdapter(PickPolicy.Retail)).All.Single(c => c.Id == id);
}
