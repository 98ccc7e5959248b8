using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>The planted faults of the parts variant indoors (issues 41, 53; PartsObjectFaults for Always2D and held parts): each caught on the pr profile by every invariant it names, and the fault model with no defect answers as core.</summary>
public sealed class PartsFaultsAreCaught(ITestOutputHelper output)
{
    public static TheoryData<string> FaultIds => new(PartsIndoorFaults.All.Concat(PartsFrameFaults.All).Concat(PartsShapeFaults.All).Concat(PartsObjectFaults.All).Concat(PartsStaleFaults.All).Select(f => f.Id));

    [Theory(DisplayName = "Parts-indoor planted fault is caught in process by every invariant it names, independent ones included where retail is exact")]
    [MemberData(nameof(FaultIds))]
    public void FaultIsCaught(string faultId)
    {
        var fault = PlantedFaults.Find(faultId)!;
        var impl = PlantedFaults.Create(faultId);
        Assert.Contains("PARTS-INDOOR-CONFORMANCE", fault.CaughtBy);
        foreach (var id in fault.CaughtBy)
        {
            var result = InvariantCatalogue.Find(id)!.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(id), maxClasses: 1);
            Assert.True(result.Status == ResultStatus.Failed, $"{faultId} should be caught by {id}");
            output.WriteLine($"{faultId} caught by {id} after {result.Cases} cases: {result.Violation!.Message}");
        }
    }

    [Fact(DisplayName = "PARTS-INDOOR-CONFORMANCE: the parts fault model with no defect answers exactly as core on the pr cases (the faults differ from retail by their defect alone)")]
    public void ModelWithoutDefectIsCore() =>
        Assert.Equal(ResultStatus.Passed, PropertyRun.Check(PartsIndoorInvariants.Conformance, output, new PartsFaultyPhysics(null)).Status);
}
