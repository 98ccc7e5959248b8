using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Props.Judging;

/// <summary>
/// Issue 27: where an invariant's oracle honours a declared switch it keeps judging under it instead of going NOT TESTED:
/// the reference declaring the switch passes, and the same deviation served while declaring retail still fails.
/// </summary>
public sealed class NarrowedUnderDeviationTests
{
    /// <summary>Gets the (switch, invariant, pick) triples whose oracle honours the switch.</summary>
    public static TheoryData<string, string, PickPolicy> Narrowed => new()
    {
        { "ace-early-return", "VISIBILITY", PickPolicy.Retail }, // steps after an interior pick skip the filter (facts §7 #7)
        { "ace-neighbour-via-visible-cells", "VISIBILITY", PickPolicy.Retail }, // an unseen portal neighbour is a hint (§7 #10)
        { "ace-load-hint-low-key", "PORTAL-TRANSIT", PickPolicy.Retail }, // the hint is looked for under its 16-bit key (§7 #11)
        { "ace-load-hint-low-key", "SCENE-SOUNDNESS", PickPolicy.Retail },
        { "ace-load-hint-low-key", "SCENE-TRANSLATION", PickPolicy.Retail },
        { "ace-no-portal-guard", "HYSTERESIS-INDOOR", PickPolicy.CurrentFirst }, // a sealed closet contains the centre (§7 #13)
    };

    [Theory(DisplayName = "judged under the declared switch with the oracle honouring it: the reference passes")]
    [MemberData(nameof(Narrowed))]
    public void DeclaredPasses(string name, string id, PickPolicy pick)
    {
        var result = InvariantCatalogue.Find(id)!.Run(DeclaredModes.Declaring(name, pick), 1_000, PropertyRun.SeedFor(id));
        Assert.Equal(ResultStatus.Passed, result.Status);
    }

    [Theory(DisplayName = "the same deviation served while retail is declared fails it")]
    [MemberData(nameof(Narrowed))]
    public void ServedUndeclaredFails(string name, string id, PickPolicy pick)
    {
        var result = InvariantCatalogue.Find(id)!.Run(DeclaredModes.DeclaringRetail(DeclaredModes.Declaring(name, pick)), 1_000, PropertyRun.SeedFor(id), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, result.Status);
    }
}
