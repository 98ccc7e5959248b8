using AcPhys.Fuzz.Targets;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using Xunit;

namespace AcPhys.Fuzz.Tests;

/// <summary>Triage under a stateful planted fault: <c>no-reset</c> keeps the previous query's cells in the array.</summary>
public sealed class StatefulFaultTriageTests
{
    [Fact]
    public void Walk_findings_under_no_reset_shrink_to_regressions_that_fail_on_a_fresh_implementation()
    {
        // As triage does: classify every input, group by (invariant, signature), minimise the smallest of each group.
        var target = (WalkTarget)FuzzTargets.Find("walk")!;
        var groups = Directory.EnumerateFiles(Path.Combine(RepoPaths.Root, "corpus", "fuzz", "walk"))
            .Order(StringComparer.Ordinal)
            .Select(File.ReadAllBytes)
            .Select(data => (Data: data, Finding: target.Classify(data, "no-reset")))
            .Where(x => x.Finding is not null)
            .GroupBy(x => (x.Finding!.Key, x.Finding.Signature))
            .Select(g => g.OrderBy(x => x.Data.Length).First().Finding!)
            .ToList();
        Assert.NotEmpty(groups);

        foreach (var finding in groups)
        {
            var entry = target.Minimise(finding, "no-reset", "test");

            Assert.NotNull(entry);
            Assert.Equal(finding.Key, entry.Invariant);
            Assert.Equal(finding.Key, InvariantCatalogue.CheckEntry(PlantedFaults.Create("no-reset"), entry)?.InvariantId);
        }
    }
}
