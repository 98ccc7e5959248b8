using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Judging;
using AcPhys.Spec.Running;

namespace AcPhys.Props.Judging;

/// <summary>
/// Issue 41, "the intended line is proved": a conformance finding names a declaration only when the port's answers equal
/// the declared reference on the shrunk case, the original and fresh cases of its class. No planted fault that is not a
/// documented deviation is ever called intended, a port bug that only reorders or only adds cells is not either, and a
/// planted fault served under any declaration still fails the gate.
/// </summary>
public sealed class IntendedIsProvedTests
{
    private const int Cases = 1_000;

    // The planted faults that ARE a documented deviation (or the other pick) served undeclared: a declaration may explain them.
    private static readonly string[] Deviations = ["no-hysteresis", "sticky-pick", "no-hysteresis-indoor", "ace-hint-key", "early-return-undeclared", "ace-announced-retail", "ace-box-side-undeclared"];

    /// <summary>Gets every planted fault that is not a documented deviation.</summary>
    public static TheoryData<string> NotDeviations => new(PlantedFaults.All.Select(f => f.Id).Where(id => !Deviations.Contains(id)));

    /// <summary>Gets every declaration a port can add: each fidelity name, and the current-first pick.</summary>
    public static IEnumerable<(string Label, PickPolicy? Pick, IndoorFidelity? Indoor, OutdoorFidelity? Outdoor)> Declarations()
    {
        foreach (string name in FidelityNames.Known)
        {
            Assert.True(FidelityNames.TryParse([name], out var indoor, out var outdoor, out _));
            yield return (name, null, indoor, outdoor);
        }

        yield return ("pick current-first", PickPolicy.CurrentFirst, null, null);
    }

    [Theory(DisplayName = "INTENDED-PROVED: a planted fault that is not a documented deviation is never called intended by any conformance finding")]
    [MemberData(nameof(NotDeviations))]
    public void FaultIsNeverIntended(string faultId)
    {
        var impl = PlantedFaults.Create(faultId);
        foreach (var invariant in ConformanceInvariants.Every.Where(i => i.IsTestable(impl)))
        {
            var result = invariant.Run(impl, Cases, PropertyRun.SeedFor(invariant.Id), maxClasses: 1);
            if (result.Status != ResultStatus.Failed || result.Violation?.Case is not AnyCase shrunk)
            {
                continue;
            }

            var intent = IntendedUnder.Explain(impl, invariant.Id, [.. new[] { shrunk, result.Original?.Case }.OfType<AnyCase>().Distinct()]);
            // Null: the case no longer fails when asked again (a fault whose answers depend on earlier calls, e.g. no-reset).
            Assert.True(intent?.Declaration is null, $"{faultId} / {invariant.Id}: called intended under {intent?.Declaration}");
        }
    }

    /// <summary>Gets every planted fault PARTS-INDOOR-CONFORMANCE is expected to catch (the parts variant indoors).</summary>
    public static TheoryData<string> PartsFaults => new(PlantedFaults.All.Where(f => f.CaughtBy.Contains(PartsIndoorInvariants.Conformance.Id) && !Deviations.Contains(f.Id)).Select(f => f.Id));

    [Theory(DisplayName = "INTENDED-PROVED: a port bug that only reorders or only adds cells is never called intended (find_cell and the parts list indoors)")]
    [InlineData("reorder", "FIND-CELL-CONFORMANCE")]
    [InlineData("add", "FIND-CELL-CONFORMANCE")]
    [InlineData("reorder", "PARTS-INDOOR-CONFORMANCE")]
    [InlineData("add", "PARTS-INDOOR-CONFORMANCE")]
    public void ReorderingOrAddingIsNeverIntended(string bug, string invariantId)
    {
        var port = new RewrittenAnswers(ReferenceAdapter.Instance, bug == "reorder" ? RewrittenAnswers.Reversed : RewrittenAnswers.WithExtraCell);
        var invariant = ConformanceInvariants.Every.Single(i => i.Id == invariantId);
        var result = invariant.Run(port, Cases, PropertyRun.SeedFor(invariantId), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, result.Status);
        var intent = IntendedUnder.Explain(port, invariantId, [.. new[] { result.Violation!.Case, result.Original?.Case }.OfType<AnyCase>().Distinct()]);
        Assert.NotNull(intent);
        Assert.Null(intent.Declaration);
        Assert.NotNull(intent.Differs);
    }

    [Theory(DisplayName = "INTENDED-PROVED: a parts fault indoors fails PARTS-INDOOR-CONFORMANCE and its finding gets the proved intended line: no declaration, what differs")]
    [MemberData(nameof(PartsFaults))]
    public void PartsFaultGetsTheProvedIntendedLine(string faultId)
    {
        var impl = PlantedFaults.Create(faultId);
        var result = PartsIndoorInvariants.Conformance.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(PartsIndoorInvariants.Conformance.Id), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, result.Status);
        var intent = IntendedUnder.Explain(impl, PartsIndoorInvariants.Conformance.Id, [.. new[] { result.Violation!.Case, result.Original?.Case }.OfType<AnyCase>().Distinct()]);
        Assert.NotNull(intent); // computed: the finding is a conformance finding the declarations were tried on
        Assert.Null(intent.Declaration);
        Assert.NotNull(intent.Differs);
    }

    [Fact(DisplayName = "INTENDED-PROVED: a documented deviation served undeclared is still named (early-return-undeclared: ace-early-return)")]
    public void DeviationIsNamed()
    {
        var impl = PlantedFaults.Create("early-return-undeclared");
        var result = ConformanceInvariants.FindCell.Run(impl, 5_000, PropertyRun.SeedFor("FIND-CELL-CONFORMANCE"), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, result.Status);
        var intent = IntendedUnder.Explain(impl, "FIND-CELL-CONFORMANCE", [.. new[] { result.Violation!.Case, result.Original?.Case }.OfType<AnyCase>().Distinct()]);
        Assert.Contains("ace-early-return", intent?.Declaration, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "INTENDED-PROVED: a documented deviation of the parts list indoors served undeclared is named (ace-transition-filter)")]
    public void PartsDeviationIsNamed()
    {
        var impl = DeclaredModes.DeclaringRetail(DeclaredModes.Declaring("ace-transition-filter", PickPolicy.Retail));
        var result = PartsIndoorInvariants.Conformance.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(PartsIndoorInvariants.Conformance.Id), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, result.Status);
        var intent = IntendedUnder.Explain(impl, PartsIndoorInvariants.Conformance.Id, [.. new[] { result.Violation!.Case, result.Original?.Case }.OfType<AnyCase>().Distinct()]);
        Assert.Contains("ace-transition-filter", intent?.Declaration, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "INTENDED-PROVED: ACE's box-side pairing at a building door served undeclared (ace-box-side-undeclared, facts §7 #14) fails PARTS-INDOOR-CONFORMANCE and is named: ace-box-side-pairing")]
    public void BoxSideDeviationIsNamed()
    {
        var impl = PlantedFaults.Create("ace-box-side-undeclared");
        Assert.Equal(IndoorFidelity.Retail, impl.Indoor); // it declares retail
        var result = PartsIndoorInvariants.Conformance.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(PartsIndoorInvariants.Conformance.Id), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, result.Status);
        var intent = IntendedUnder.Explain(impl, PartsIndoorInvariants.Conformance.Id, [.. new[] { result.Violation!.Case, result.Original?.Case }.OfType<AnyCase>().Distinct()]);
        Assert.Equal("\"fidelity\": [\"ace-box-side-pairing\"]", intent?.Declaration);
    }

    [Fact(DisplayName = "INTENDED-PROVED: the same port declaring ace-box-side-pairing passes every conformance invariant (the declaration excuses its deviation); declaring ace it fails (ACE's other differences are not served)")]
    public void BoxSideDeviationDeclaredPasses()
    {
        Assert.True(FidelityNames.TryParse(["ace-box-side-pairing"], out var indoor, out var outdoor, out _));
        var declared = DeclaredFault.Create("ace-box-side-undeclared", null, indoor, outdoor);
        foreach (var invariant in ConformanceInvariants.Every.Where(i => i.IsTestable(declared)))
        {
            var result = invariant.Run(declared, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(invariant.Id), maxClasses: 1);
            Assert.True(result.Status == ResultStatus.Passed, $"{invariant.Id} under ace-box-side-pairing: {result.Status} {result.Violation?.Message}");
        }

        Assert.True(FidelityNames.TryParse([FidelityNames.Ace], out var ace, out var aceOutdoor, out _));
        var overDeclared = DeclaredFault.Create("ace-box-side-undeclared", null, ace, aceOutdoor);
        Assert.Equal(ResultStatus.Failed, ConformanceInvariants.FindCell.Run(overDeclared, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(ConformanceInvariants.FindCell.Id), maxClasses: 1).Status);
    }

    [Theory(DisplayName = "INTENDED-PROVED: a planted fault that is not a documented deviation, served under any declaration, still fails the gate (its catchers or a conformance invariant)")]
    [MemberData(nameof(NotDeviations))]
    public void DeclaringNeverTurnsAFaultGreen(string faultId)
    {
        var fault = PlantedFaults.Find(faultId)!;
        var judges = fault.CaughtBy.Select(id => InvariantCatalogue.Find(id)!).Concat(ConformanceInvariants.All).Distinct().ToList();
        foreach (var (label, pick, indoor, outdoor) in Declarations())
        {
            var declared = DeclaredFault.Create(faultId, pick, indoor, outdoor);
            bool failed = judges.Any(i => i.Run(declared, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(i.Id), maxClasses: 1).Status == ResultStatus.Failed);
            Assert.True(failed, $"{faultId} declaring {label}: the gate passed");
        }
    }
}
