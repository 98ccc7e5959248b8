using AcPhys.Spec.Faults;
using AcPhys.Spec.Running;
using AcPhys.Studies.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Tradeoffs;

/// <summary>The budget curve's one assumption: a run at budget N checks the first N cases of the same seeded sequence.</summary>
public sealed class BudgetCurveTests(ITestOutputHelper output)
{
    [Fact(DisplayName = "BUDGET: a fault first caught at case k is caught with a cap of k and missed with a cap of k - 1")]
    public void CasesToDetectIsAPrefixProperty()
    {
        var fault = PlantedFaults.Find("no-eps-snap")!;
        ulong seed = Profile.Pr.BaseSeed!.Value;
        var full = BudgetCurve.Measure(fault, seed, 5_000);
        output.WriteLine($"{fault.Id}: first caught at case {full.CasesToDetect} by {full.Invariant}");
        Assert.NotNull(full.CasesToDetect);
        long k = full.CasesToDetect!.Value;
        Assert.True(k > 1, "pick a fault/seed that needs more than one case, or the test proves nothing");
        Assert.Equal(k, BudgetCurve.Measure(fault, seed, (int)k).CasesToDetect);
        Assert.Null(BudgetCurve.Measure(fault, seed, (int)k - 1).CasesToDetect);
    }

    [Fact(DisplayName = "BUDGET: detection probability counts the seeds caught within the budget")]
    public void ProbabilityCountsSeeds()
    {
        DetectionSample[] samples =
        [
            new("f", 1, 3, "X", TimeSpan.Zero), new("f", 2, 10, "X", TimeSpan.Zero), new("f", 3, null, null, TimeSpan.Zero), new("f", 4, 1, "X", TimeSpan.Zero),
        ];
        Assert.Equal(0.25, BudgetCurve.Probability(samples, 1));
        Assert.Equal(0.5, BudgetCurve.Probability(samples, 9));
        Assert.Equal(0.75, BudgetCurve.Probability(samples, 10));
        Assert.Equal(0.75, BudgetCurve.Probability(samples, 1_000_000));
        Assert.NotEqual(BudgetCurve.SeedAt(8, 0), BudgetCurve.SeedAt(8, 1));
    }
}
