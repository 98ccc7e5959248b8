using AcPhys.Contract;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>
/// The exact indoor invariants: each as an FsCheck property against the reference, and each shown to bite — a
/// test adapter with one defect (<see cref="ExactDefects"/>) violates it on a concrete scene where the reference holds.
/// </summary>
public sealed class IndoorExactInvariantProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "HITS-INTERIOR: HitsInteriorCell is set exactly when indoor or an env cell was entered")]
    public void HitsInterior() => PropertyRun.Check(IndoorExactInvariants.HitsInterior, output);

    [Fact(DisplayName = "NEIGHBOURS-COMPLETE: every loaded neighbour a sphere intersects is a candidate")]
    public void NeighboursComplete() => PropertyRun.Check(IndoorClosureInvariants.NeighboursComplete, output);

    [Fact(DisplayName = "BUILDING-ENTRY-COMPLETE: every valid building portal's cell a sphere intersects is a candidate")]
    public void BuildingEntryComplete() => PropertyRun.Check(IndoorClosureInvariants.BuildingEntryComplete, output);

    [Fact(DisplayName = "ENV-CANDIDATE-JUSTIFIED: every env candidate is the position or intersected behind a portal")]
    public void EnvCandidateJustified() => PropertyRun.Check(IndoorClosureInvariants.EnvCandidateJustified, output);

    [Fact(DisplayName = "LAND-VIA-EXIT: from indoors, land cells come exactly from straddled exit planes")]
    public void LandViaExit() => PropertyRun.Check(IndoorExactInvariants.LandViaExit, output);

    [Fact(DisplayName = "PICK-FIRST-ENV: the first env candidate containing sphere 0's centre is picked")]
    public void PickFirstEnv() => PropertyRun.Check(IndoorExactInvariants.PickFirstEnv, output);

    [Fact(DisplayName = "HITS-INTERIOR: a port that sets the flag only on an interior pick is caught at a front door")]
    public void HitsInteriorBites() => Bites(ExactBites.HitsOnlyFromPick);

    [Fact(DisplayName = "NEIGHBOURS-COMPLETE: a closure over a snapshot misses room 1 behind room 0 entered from land")]
    public void NeighboursCompleteBites() => Bites(ExactBites.SnapshotClosure);

    [Fact(DisplayName = "BUILDING-ENTRY-COMPLETE: a port that enters only the first building portal misses the back door's room")]
    public void BuildingEntryCompleteBites() => Bites(ExactBites.SecondBuildingPortal);

    [Fact(DisplayName = "ENV-CANDIDATE-JUSTIFIED: a neighbour added by its portal's infinite plane alone is caught")]
    public void EnvCandidateJustifiedBitesPlane() => Bites(ExactBites.NeighbourByPlane);

    [Fact(DisplayName = "ENV-CANDIDATE-JUSTIFIED: entering a building portal with portal index 0xFFFF is caught")]
    public void EnvCandidateJustifiedBitesInvalidPortal() => Bites(ExactBites.InvalidBuildingPortal);

    [Fact(DisplayName = "LAND-VIA-EXIT: outdoor cells added for an exit no sphere straddles are caught")]
    public void LandViaExitBitesUnstraddled() => Bites(ExactBites.ExitWithoutStraddle);

    [Fact(DisplayName = "LAND-VIA-EXIT: a transition that drops the outdoor cells of a straddled exit is caught")]
    public void LandViaExitBitesDropped() => Bites(ExactBites.NoOutdoorCellsOnExit);

    [Fact(DisplayName = "PICK-FIRST-ENV: a reversed interior pick (last env hit wins) is caught in overlapping cells")]
    public void PickFirstEnvBitesReversed() => Bites(ExactBites.LastEnvWins);

    [Fact(DisplayName = "PICK-FIRST-ENV: a pick decided by the body's last sphere instead of sphere 0 is caught")]
    public void PickFirstEnvBitesOtherSphere() => Bites(ExactBites.LastSphereDecides);

    private void Bites(ExactBite bite)
    {
        var reference = bite.Invariant.Check(ReferenceAdapter.Instance, bite.Case);
        var caught = bite.Invariant.Check(bite.Defect, bite.Case);
        output.WriteLine($"{bite.Invariant.Id} on {bite.Case}");
        output.WriteLine($"  reference: {reference.Verdict}; {bite.Defect.Name}: {caught.Verdict} {caught.Message}");
        Assert.Equal(bite.ReferenceApplies ? Verdict.Holds : Verdict.Vacuous, reference.Verdict);
        Assert.True(caught.IsViolation, $"{bite.Defect.Name} should violate {bite.Invariant.Id}");
    }
}
