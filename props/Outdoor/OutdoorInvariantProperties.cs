using AcPhys.Contract;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using Xunit.Abstractions;

namespace AcPhys.Props.Outdoor;

/// <summary>Each outdoor-query and walk invariant as an FsCheck property against the reference core.</summary>
public sealed class OutdoorInvariantProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "COVERAGE: every cell the disc overlaps (3 x 3 neighbourhood) is in the set")]
    public void Coverage() => PropertyRun.Check(OutdoorInvariants.Coverage, output);

    [Fact(DisplayName = "NONFINITE-SPHERE-ENDS-LOOP: a sphere with a NaN or infinite centre adds nothing and ends the sphere loop (hardening)")]
    public void NonFiniteSphereEndsLoop() => PropertyRun.Check(OutdoorInvariants.NonFiniteSphereEndsLoop, output);

    [Fact(DisplayName = "SOUNDNESS: every cell in the set is within r + 1 mm of a centre per axis")]
    public void Soundness() => PropertyRun.Check(OutdoorInvariants.Soundness, output);

    [Fact(DisplayName = "NEIGHBOUR-SYMMETRY: the set is the same from any adjacent landblock's frame")]
    public void NeighbourSymmetry() => PropertyRun.Check(OutdoorInvariants.NeighbourSymmetry, output);

    [Fact(DisplayName = "TRANSLATION: shifting by whole cells or blocks shifts the set alike")]
    public void Translation() => PropertyRun.Check(OutdoorInvariants.Translation, output);

    [Fact(DisplayName = "SPHERE-ORDER: the set does not depend on the order of the spheres")]
    public void SphereOrder() => PropertyRun.Check(OutdoorInvariants.SphereOrder, output);

    [Fact(DisplayName = "STABLE-PICK: the retail pick depends on the position alone")]
    public void StablePick() => PropertyRun.Check(OutdoorInvariants.StablePick, output);

    [Fact(DisplayName = "HYSTERESIS: the current-first pick keeps a current cell that still contains the centre")]
    public void Hysteresis() => PropertyRun.Check(OutdoorInvariants.Hysteresis, output, ReferenceAdapter.CurrentFirst);

    [Fact(DisplayName = "NO-BOUNDARY-FREEZE: after every step the containing cell is the land cell under the centre")]
    public void NoBoundaryFreeze() => PropertyRun.Check(WalkInvariants.NoBoundaryFreeze, output);

    [Fact(DisplayName = "NO-BOUNDARY-FREEZE (current-first): hysteresis never freezes the cell either")]
    public void NoBoundaryFreezeCurrentFirst() => PropertyRun.Check(WalkInvariants.NoBoundaryFreeze, output, ReferenceAdapter.CurrentFirst);

    [Fact(DisplayName = "WALK-REVERSIBLE: walking a path and back ends in the start cell")]
    public void WalkReversible() => PropertyRun.Check(WalkInvariants.WalkReversible, output);

    [Fact(DisplayName = "MAP-EDGE-WALK: walks along and off the map edge never produce ids outside the map")]
    public void MapEdgeWalk() => PropertyRun.Check(WalkInvariants.MapEdgeWalk, output);
}

/// <summary>The parts / bounding-box variant as FsCheck properties.</summary>
public sealed class PartsInvariantProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "PARTS-COVERAGE: every cell a part's box overlaps, and the anchor's cell, is in the set")]
    public void PartsCoverage() => PropertyRun.Check(PartsInvariants.PartsCoverage, output);

    [Fact(DisplayName = "PARTS-SOUNDNESS: every cell lies in the range of the anchor's cell and the parts' boxes")]
    public void PartsSoundness() => PropertyRun.Check(PartsInvariants.PartsSoundness, output);
}
