using AcPhys.Contract;
using AcPhys.Formats.Dat.Container;
using AcPhys.Props.Dat;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.DatContainers;

/// <summary>
/// DAT-WORLD-GATE: walks through scenes extracted from a dat world hold on the reference, and a planted indoor fault is
/// caught there, naming the landblock and the cell.
/// </summary>
public sealed class DatWorldGateTests(ITestOutputHelper output)
{
    [Fact(DisplayName = "DAT-WORLD-GATE: every walk through every block of the corpus dat world holds on the reference; the sample is deterministic")]
    public void ReferenceHolds()
    {
        using var world = CorpusWorld();
        var candidates = DatWorldGate.Candidates(world);
        Assert.Equal(6, candidates.Count); // the seven corpus scene walks, two of which share one cottage
        Assert.Equal(DatWorldGate.Sample(candidates, 4), DatWorldGate.Sample(candidates, 4));
        var result = DatWorldGate.Run(world, ReferenceAdapter.Instance, candidates, candidates.Count);
        output.WriteLine($"{result.Cells} cells, {result.Walks} walks, {result.Findings.Count} findings, {result.Refused.Count} refused");
        Assert.Empty(result.Refused);
        // Every portal of the corpus scenes is a wall (no floor or ceiling portal): one walk through each.
        var scenes = DatTestSupport.CorpusSceneWalks.Select(e => e.Entry.SceneWalk!.Scene).DistinctBy(AcPhys.Formats.Scenes.SceneJson.WriteCompact).ToList();
        Assert.Equal(scenes.Sum(s => s.Cells.Count), result.Cells);
        Assert.Equal(scenes.Sum(s => s.Cells.Sum(c => c.Portals.Count)), result.Walks);
        Assert.Empty(result.Findings);
    }

    [Theory(DisplayName = "DAT-WORLD-GATE: a planted indoor fault fails walks in the dat world, the finding naming the block and the start cell")]
    [InlineData("outdoor-wins", "INTERIOR-WINS")]
    [InlineData("no-visibility-filter", "VISIBILITY")]
    [InlineData("hits-interior-unset", "HITS-INTERIOR")]
    public void PlantedFaultIsCaught(string fault, string invariant)
    {
        using var world = CorpusWorld();
        var candidates = DatWorldGate.Candidates(world);
        var result = DatWorldGate.Run(world, PlantedFaults.Create(fault), candidates, candidates.Count);
        output.WriteLine(string.Join("\n", result.Findings));
        var f = Assert.Single(result.Findings, f => f.Violation.InvariantId == invariant && f.Block.Value == 0xA9B4 && f.Walk.Cell.Value == 0xA9B40100 && f.Walk.Portal == 0);
        Assert.Contains("landblock 0xA9B4, walk from 0xA9B40100", f.ToString());
    }

    private static DatWorld CorpusWorld()
    {
        var (cell, portal) = SceneContainers.Records(DatTestSupport.CorpusSceneWalks.Select(e => e.Entry.SceneWalk!.Scene));
        return new DatWorld(
            DatContainer.Open(new MemoryBlockSource(DatContainerWriter.ToBytes(cell, DatSet.Cell, 256), "cell.dat")),
            DatContainer.Open(new MemoryBlockSource(DatContainerWriter.ToBytes(portal, DatSet.Portal, 256), "portal.dat")));
    }
}
