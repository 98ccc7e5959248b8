using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using Xunit.Abstractions;

namespace AcPhys.Props.Land;

/// <summary>Each LandDefs invariant as an FsCheck property over the biased case generator, against the reference core.</summary>
public sealed class LandInvariantProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "LCOORD-ROUNDTRIP: lcoord_to_gid and gid_to_lcoord are inverse on the whole map")]
    public void LcoordRoundTrip() => PropertyRun.Check(LandInvariants.LcoordRoundTrip, output);

    [Fact(DisplayName = "LCOORD-BLOCK: the block part of gid_to_lcoord is blockid_to_lcoord")]
    public void LcoordBlock() => PropertyRun.Check(LandInvariants.LcoordBlock, output);

    [Fact(DisplayName = "OUTSIDE-LCOORD-GEOMETRY: get_outside_lcoord is the floored 24 m column of the point")]
    public void OutsideLcoordGeometry() => PropertyRun.Check(LandInvariants.OutsideLcoordGeometry, output);

    [Fact(DisplayName = "ADJUST-GEOMETRY: AdjustToOutside picks the column under the snapped point and fails only off the map")]
    public void AdjustGeometry() => PropertyRun.Check(LandInvariants.AdjustGeometry, output);

    [Fact(DisplayName = "ADJUST-IDEMPOTENT: re-seating a re-seated point changes nothing but an EPS-band snap or a float32 line tie")]
    public void AdjustIdempotent() => PropertyRun.Check(LandInvariants.AdjustIdempotent, output);

    [Fact(DisplayName = "ADJUST-PRESERVES-POSITION: the world point survives a re-seat within 2.1e-4 m")]
    public void AdjustPreservesPosition() => PropertyRun.Check(LandInvariants.AdjustPreservesPosition, output);

    [Fact(DisplayName = "ADJUST-RANGE: a re-seat yields a land cell and x, y in [0, 192) inside its closed square")]
    public void AdjustRange() => PropertyRun.Check(LandInvariants.AdjustRange, output);

    [Fact(DisplayName = "MAP-EDGE: lcoords 0 and 2039 valid, -1 and 2040 and block byte 0xFF rejected without exceptions")]
    public void MapEdge() => PropertyRun.Check(LandInvariants.MapEdge, output);

    [Fact(DisplayName = "NONFINITE-REJECTED: NaN and infinite coordinates never yield a cell")]
    public void NonFiniteRejected() => PropertyRun.Check(LandInvariants.NonFiniteRejected, output);
}
