using AcPhys.Contract;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Outdoor;

/// <summary>Issue #18: a run reports findings, one per root cause, and keeps searching past an invariant's first failure.</summary>
public sealed class FindingsAreGrouped(ITestOutputHelper output)
{
    // The LandDefs and outdoor-query invariants: where the non-finite and exact-edge faults land.
    private static readonly Invariant[] Outdoor = [.. LandInvariants.All, .. OutdoorInvariants.All, ConformanceInvariants.LandDefs, ConformanceInvariants.OutsideCells, ConformanceInvariants.FindCellQuery];

    [Fact(DisplayName = "FINDINGS: one root cause (a checked cast throwing on non-finite and huge values) breaks many invariants and is reported as few findings that name them all")]
    public void OneRootCauseIsOneFinding()
    {
        var results = Run(PlantedFaults.Create("checked-cast"));
        var failed = results.Where(r => r.Status == ResultStatus.Failed).Select(r => r.Invariant.Id).ToArray();
        var findings = Findings.Of(results);
        Show(findings);

        Assert.True(failed.Length >= 6, $"only {failed.Length} invariants failed: {string.Join(", ", failed)}");
        Assert.True(findings.Count <= 3, $"{findings.Count} findings for one root cause");
        Assert.All(findings, f => Assert.Contains(f.Cause, new[] { "nonfinite", "huge" }));
        Assert.Equal(failed.Order(), findings.SelectMany(f => f.Invariants).Distinct().Order()); // every failing invariant is named
    }

    [Fact(DisplayName = "FINDINGS: a second, unrelated bug in the same implementation (touch-inclusive behind checked-cast) is a finding of its own in the same run")]
    public void SecondBugIsReportedInTheSameRun()
    {
        var results = Run(PlantedFaults.Combine("checked-cast", "touch-inclusive"));
        var findings = Findings.Of(results);
        Show(findings);

        var second = findings.Where(f => f.Cause is not ("nonfinite" or "huge")).ToArray();
        Assert.NotEmpty(second);
        Assert.Contains(second, f => f.Invariants.Contains("OUTSIDE-CELLS-CONFORMANCE") || f.Invariants.Contains("FIND-CELL-QUERY-CONFORMANCE"));
        Assert.Contains(findings, f => f.Cause is "nonfinite" or "huge");
    }

    [Fact(DisplayName = "FINDINGS: an invariant keeps searching after its first failure and reports a further class, each shrunk")]
    public void AnInvariantReportsMoreThanOneClass()
    {
        var impl = PlantedFaults.Combine("checked-cast", "touch-inclusive");
        var r = ConformanceInvariants.OutsideCells.Run(impl, PropertyRun.Profile.CasesPerInvariant, PropertyRun.SeedFor(ConformanceInvariants.OutsideCells.Id));
        output.WriteLine($"{r.Invariant.Id}: first class {r.FailureClass}; more: {string.Join("; ", r.MoreFailures.Select(m => m.Class + " " + m.Violation.CaseText))}");
        Assert.Equal(ResultStatus.Failed, r.Status);
        Assert.NotEmpty(r.MoreFailures);
        Assert.DoesNotContain(r.FailureClass, r.MoreFailures.Select(m => m.Class));
        Assert.Equal(r.MoreFailures.Count, r.MoreFailures.Select(m => m.Class).Distinct().Count());
    }

    [Fact(DisplayName = "FINDINGS: FIND-CELL-CONFORMANCE (walks of either kind) keeps searching after its first failure too, and names its class")]
    public void WalkConformanceReportsMoreThanOneClass()
    {
        var walks = InvariantCatalogue.All.Single(i => i.Id == "FIND-CELL-CONFORMANCE");
        var r = walks.Run(PlantedFaults.Create("clamp-106"), PropertyRun.Profile.CasesPerInvariant, PropertyRun.SeedFor(walks.Id));
        output.WriteLine($"{r.Invariant.Id}: first class {r.FailureClass}; more: {string.Join("; ", r.MoreFailures.Select(m => m.Class))}");
        Assert.Equal(ResultStatus.Failed, r.Status);
        Assert.StartsWith("walk:", r.FailureClass, StringComparison.Ordinal); // a stored walk is classified, not "unclassified"
        Assert.NotEmpty(r.MoreFailures);
    }

    private static List<InvariantResult> Run(ICellPhysics impl) =>
        [.. Outdoor.Select(i => i.Run(impl, PropertyRun.Profile.CasesPerInvariant, PropertyRun.SeedFor(i.Id)))];

    private void Show(IReadOnlyList<Finding> findings)
    {
        foreach (var f in findings)
        {
            output.WriteLine($"[{f.Cause}] {string.Join(", ", f.Invariants)} — {f.Example.Violation.CaseText}");
        }
    }
}
