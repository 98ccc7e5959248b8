using AcPhys.Contract;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Land;

/// <summary>The finite domains checked whole, not sampled: every lcoord of the map and every block id × 64 land cells.</summary>
public sealed class ExhaustiveSweeps(ITestOutputHelper output)
{
    [Fact(DisplayName = "LCOORD-ROUNDTRIP (exhaustive): all 2040 x 2040 lcoords round-trip through their cell id")]
    public void EveryLcoordRoundTrips() => AssertClean(Exhaustive.AllLcoords(LandInvariants.LcoordRoundTrip, ReferenceAdapter.Instance), 2040L * 2040);

    [Fact(DisplayName = "LCOORD-ROUNDTRIP (exhaustive): every block id x 64 land cells round-trips (0xFF blocks rejected)")]
    public void EveryLandCellIdRoundTrips() => AssertClean(Exhaustive.AllLandCellIds(LandInvariants.LcoordRoundTrip, ReferenceAdapter.Instance), 65536L * 64);

    [Fact(DisplayName = "LCOORD-BLOCK (exhaustive): every block id x 64 land cells has blockid_to_lcoord as its block part")]
    public void EveryLandCellIdHasItsBlock() => AssertClean(Exhaustive.AllLandCellIds(LandInvariants.LcoordBlock, ReferenceAdapter.Instance), 65536L * 64);

    [Fact(DisplayName = "MAP-EDGE (exhaustive): every id with a 0xFF block byte is rejected by every LandDefs function")]
    public void EveryFfBlockIsRejected() => AssertClean(Exhaustive.AllLandCellIds(LandInvariants.MapEdge, ReferenceAdapter.Instance), 65536L * 64);

    [Fact(DisplayName = "Exhaustive sweeps catch a planted fault that sampling could miss: sign-extended block_y")]
    public void SweepCatchesSignExtension()
    {
        var faulty = AcPhys.Spec.Faults.PlantedFaults.Create("sign-extend-by");
        var sweep = Exhaustive.AllLandCellIds(LandInvariants.LcoordRoundTrip, faulty);
        output.WriteLine(sweep.FirstViolation?.ToString() ?? "none");
        Assert.NotNull(sweep.FirstViolation);
    }

    private void AssertClean(SweepResult sweep, long expectedCases)
    {
        output.WriteLine($"{sweep.Domain}: {sweep.Cases:N0} cases in {sweep.Elapsed.TotalMilliseconds:F0} ms ({Environment.ProcessorCount} cores)");
        Assert.Equal(expectedCases, sweep.Cases);
        Assert.Null(sweep.FirstViolation);
    }
}
