using System.Diagnostics;
using AcPhys.Formats.Cases;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>Every indoor planted fault is caught by the pr profile by an invariant it names, and shrinks to a small scene and walk.</summary>
public sealed class IndoorFaultsAreCaught(ITestOutputHelper output)
{
    public static TheoryData<string> FaultIds => new(IndoorFaults.All.Select(f => f.Id));

    [Theory(DisplayName = "Indoor planted fault is caught by its named invariants with a shrunk scene walk (sizes printed)")]
    [MemberData(nameof(FaultIds))]
    public void FaultIsCaughtAndShrinks(string faultId)
    {
        var fault = PlantedFaults.Find(faultId)!;
        var impl = PlantedFaults.Create(faultId);
        foreach (var id in fault.CaughtBy)
        {
            var stopwatch = Stopwatch.StartNew();
            var result = InvariantCatalogue.Find(id)!.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(id), maxClasses: 1);
            Assert.True(result.Status == ResultStatus.Failed, $"{faultId} should be caught by {id}");
            var shrunk = Walk(result.Violation!.Case);
            var original = Walk(result.Original!.Case);
            output.WriteLine($"{faultId} caught by {id} in {stopwatch.ElapsedMilliseconds} ms after {result.Cases} cases; shrunk to {shrunk.Size} (from {original.Size})");
            output.WriteLine("  " + result.Violation.Message);
            output.WriteLine("  " + shrunk.Recipe);
            // Smaller scene first, then fewer steps: with fewer rooms a route is shorter, so its steps are shorter too
            // and a walk that must go in and back out whole can take more of them (no-exit-transit: 4 rooms and 32
            // steps shrank to 2 rooms and 64 steps once hubs and near-touch recipes shifted the pr stream).
            Assert.True(
                Rooms(shrunk) < Rooms(original) || (Rooms(shrunk) == Rooms(original) && shrunk.Walk.Steps.Count <= original.Walk.Steps.Count),
                $"{faultId}: the shrunk case ({shrunk.Size}) is not smaller than the original ({original.Size})");
        }
    }

    private static int Rooms(SceneWalk w) => w.Scene.Cells.Count + w.Scene.UnloadedCells.Count;

    // The scene invariants' case is a scene walk; FIND-CELL-CONFORMANCE's an AnyWalk holding one.
    private static SceneWalk Walk(AnyCase? c) => Assert.IsType<AnyCase.WalkInScene>(c).Walk;
}
