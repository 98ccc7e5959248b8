using System.Diagnostics;
using AcPhys.Formats.Cases;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Outdoor;

/// <summary>Issue #3's bar: the #106 class is caught by the pr profile and shrinks to a walk a person reads at a glance (≤ 3 steps).</summary>
public sealed class BoundaryFreezeIsCaught(ITestOutputHelper output)
{
    public static TheoryData<string, string> Faults => new()
    {
        { "clamp-106", "NO-BOUNDARY-FREEZE" },
        { "trunc-floor", "NO-BOUNDARY-FREEZE" },
        { "in-cell-neighbours", "COVERAGE" },
        { "clamp-106", "COVERAGE" },
    };

    [Theory(DisplayName = "Fault is caught by the pr profile and shrinks to a walk of at most 3 steps")]
    [MemberData(nameof(Faults))]
    public void CaughtAndShrunk(string faultId, string invariantId)
    {
        var impl = PlantedFaults.Create(faultId);
        var invariant = InvariantCatalogue.Find(invariantId)!;
        var stopwatch = Stopwatch.StartNew();
        var result = invariant.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(invariantId), maxClasses: 1);
        stopwatch.Stop();
        Assert.Equal(ResultStatus.Failed, result.Status);
        output.WriteLine(PropertyRun.FailureText(result, impl));
        output.WriteLine($"detected after {result.Cases} cases, {stopwatch.Elapsed.TotalMilliseconds:F0} ms including shrinking");
        int steps = result.Violation!.Case switch
        {
            AnyCase.OutdoorWalk w => w.Walk.Steps.Count,
            AnyCase.OutdoorQuery => 0,
            _ => throw new InvalidOperationException("unexpected case type"),
        };
        Assert.InRange(steps, 0, 3);
    }
}
