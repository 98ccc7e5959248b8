using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Judging;
using AcPhys.Spec.Running;

namespace AcPhys.Props.Judging;

/// <summary>
/// Issue 27, "no false alarm from the reference in every declared mode": a retail statement a declared deviation breaks by
/// design is NOT TESTED under that declaration, with the switch named, and still judged (and failed) when the same
/// deviation is served while retail is declared.
/// </summary>
public sealed class BrokenByDesignTests
{
    /// <summary>Gets every (switch, invariant) pair the table exempts.</summary>
    public static TheoryData<string, string> Exempted
    {
        get
        {
            var data = new TheoryData<string, string>();
            foreach (var (name, id) in BrokenByDesign.Exempted)
            {
                data.Add(name, id);
            }

            return data;
        }
    }

    [Theory(DisplayName = "a retail statement a declared deviation breaks by design is NOT TESTED under it, naming the switch")]
    [MemberData(nameof(Exempted))]
    public void DeclaredIsNotTested(string name, string id)
    {
        var invariant = InvariantCatalogue.Find(id)!;
        var result = invariant.Run(DeclaredModes.Declaring(name, PickPolicy.Retail), 50, PropertyRun.SeedFor(id));
        Assert.Equal(ResultStatus.NotTested, result.Status);
        Assert.Contains($"the declared {name} breaks by design (facts §7", result.NotTestedReason, StringComparison.Ordinal);
    }

    [Theory(DisplayName = "the same statement FAILS when the deviation is served while retail is declared (the exemption is measured, and the gate still bites)")]
    [MemberData(nameof(Exempted))]
    public void ServedUndeclaredFails(string name, string id)
    {
        var undeclared = DeclaredModes.DeclaringRetail(DeclaredModes.Declaring(name, PickPolicy.Retail));
        var invariant = InvariantCatalogue.Find(id)!;
        Assert.Null(invariant.WhyNotTestable(undeclared));
        var result = invariant.Run(undeclared, 1_000, PropertyRun.SeedFor(id), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, result.Status);
    }

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE and the other conformance invariants: never exempted; they compare in the declared mode")]
    public void ConformanceIsNeverExempted()
    {
        var ace = DeclaredModes.Declaring(FidelityNames.Ace, PickPolicy.Retail);
        Assert.All(ConformanceInvariants.Every, c => Assert.Null(c.WhyNotTestable(ace)));
        Assert.DoesNotContain(BrokenByDesign.Exempted, e => ConformanceInvariants.Every.Any(c => c.Id == e.InvariantId));
        Assert.All(BrokenByDesign.Exempted, e => Assert.NotNull(InvariantCatalogue.Find(e.InvariantId)));
    }

    [Fact(DisplayName = "retail declared: no invariant is exempted, only the operations and the pick decide what is tested")]
    public void RetailExemptsNothing() =>
        Assert.All(InvariantCatalogue.All, i => Assert.Equal(i.WhyNotTestable(Op.All, PickPolicy.Retail), i.WhyNotTestable(ReferenceAdapter.Instance)));

    [Fact(DisplayName = "PORTAL-TRANSIT under ace: the reason names the switch and the facts section")]
    public void ReasonNamesSwitchAndFacts()
    {
        string? why = IndoorInvariants.PortalTransit.WhyNotTestable(DeclaredModes.Declaring(FidelityNames.Ace, PickPolicy.Retail));
        Assert.Equal("a retail statement the declared ace-keeps-stale-cells breaks by design (facts §7 #6, §4 step 1: the array is not cleared between the queries of a walk)", why);
    }

    [Fact(DisplayName = "VISIBILITY, SCENE-TRANSLATION, NEVER-NULL under ace-keeps-stale-cells: judged (the stale array lives for one walk and breaks none of them; issue 41)")]
    public void StaleCellsExemptOnlyWhatTheyBreak()
    {
        var stale = DeclaredModes.Declaring("ace-keeps-stale-cells", PickPolicy.Retail);
        Assert.Null(IndoorInvariants.Visibility.WhyNotTestable(stale));
        Assert.Equal(["PORTAL-TRANSIT", "NO-TUNNEL", "SCENE-SOUNDNESS", "ENV-CANDIDATE-JUSTIFIED", "TIES-PINNED-INDOOR"], BrokenByDesign.Exempted.Where(e => e.Switch == "ace-keeps-stale-cells").Select(e => e.InvariantId));
    }
}
