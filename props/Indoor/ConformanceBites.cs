using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Props.Indoor;

/// <summary>Each conformance invariant passes the reference and catches a planted fault of its domain.</summary>
public sealed class ConformanceBites
{
    [Theory(DisplayName = "LANDDEFS-CONFORMANCE: the reference conforms and trunc-floor does not")]
    [InlineData("LANDDEFS-CONFORMANCE", "trunc-floor")]
    public void LandDefs(string invariant, string fault) => Bites(invariant, fault);

    [Theory(DisplayName = "OUTSIDE-CELLS-CONFORMANCE: the reference conforms and sphere-leak does not")]
    [InlineData("OUTSIDE-CELLS-CONFORMANCE", "sphere-leak")]
    public void OutsideCells(string invariant, string fault) => Bites(invariant, fault);

    [Theory(DisplayName = "FIND-CELL-CONFORMANCE: the reference conforms and snapshot-closure does not")]
    [InlineData("FIND-CELL-CONFORMANCE", "snapshot-closure")]
    public void FindCell(string invariant, string fault) => Bites(invariant, fault);

    private static void Bites(string invariantId, string faultId)
    {
        var invariant = InvariantCatalogue.Find(invariantId)!;
        Assert.Equal(ResultStatus.Passed, invariant.Run(Spec.Adapters.ReferenceAdapter.Instance, 1000, PropertyRun.SeedFor(invariantId)).Status);
        Assert.Equal(ResultStatus.Failed, invariant.Run(PlantedFaults.Create(faultId), Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(invariantId)).Status);
    }
}
