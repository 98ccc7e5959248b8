using AcPhys.Contract;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>Each invariant of the parts variant indoors as an FsCheck property against the reference core (retail, and ACE declared).</summary>
public sealed class PartsIndoorInvariantProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS: every listed env cell is reached by a part's box, land cells lie in the parts' range, static placement keeps only what the anchor sees")]
    public void Soundness() => PropertyRun.Check(PartsIndoorInvariants.Soundness, output);

    [Fact(DisplayName = "PARTS-INDOOR-COVERAGE: a neighbour a part's box reaches through a portal is listed, by any part")]
    public void Coverage() => PropertyRun.Check(PartsIndoorInvariants.Coverage, output);

    [Fact(DisplayName = "PARTS-BUILDING-ENTRY: a building cell a part's box reaches through its door is listed, HitsInteriorCell set")]
    public void BuildingEntry() => PropertyRun.Check(PartsIndoorInvariants.BuildingEntry, output);

    [Fact(DisplayName = "PARTS-INDOOR-CONFORMANCE: the parts list equals the reference's, both kinds, in order")]
    public void Conformance() => PropertyRun.Check(PartsIndoorInvariants.Conformance, output);

    [Fact(DisplayName = "PARTS-INDOOR-COVERAGE (ACE declared): no false alarm with every ACE indoor switch declared")]
    public void CoverageAce() => PropertyRun.Check(PartsIndoorInvariants.Coverage, output, new ReferenceAdapter { Indoor = AcPhys.Core.IndoorFidelity.Ace });
}
