using System.Diagnostics;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Land;

/// <summary>Proof that the invariants bite: every planted fault is caught by the pr profile, by the invariants it names.</summary>
public sealed class PlantedFaultsAreCaught(ITestOutputHelper output)
{
    public static TheoryData<string> FaultIds => new(PlantedFaults.All.Except(IndoorFaults.All).Select(f => f.Id)); // indoor faults: props/Indoor/IndoorFaultsAreCaught

    [Theory(DisplayName = "Planted fault is caught by the pr profile, by an invariant it names, with a shrunk case")]
    [MemberData(nameof(FaultIds))]
    public void FaultIsCaught(string faultId)
    {
        var fault = PlantedFaults.Find(faultId)!;
        var impl = PlantedFaults.Create(faultId);
        var stopwatch = Stopwatch.StartNew();
        var caught = new List<InvariantResult>();
        foreach (var invariant in InvariantCatalogue.All)
        {
            var result = invariant.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(invariant.Id));
            if (result.Status == ResultStatus.Failed)
            {
                caught.Add(result);
                output.WriteLine(PropertyRun.FailureText(result, impl));
            }
        }

        output.WriteLine($"{faultId}: caught by {string.Join(", ", caught.Select(r => r.Invariant.Id))} in {stopwatch.ElapsedMilliseconds} ms");
        Assert.NotEmpty(caught);
        Assert.Contains(caught, r => fault.CaughtBy.Contains(r.Invariant.Id));
        Assert.All(caught, r => Assert.NotNull(r.Violation));
    }

    [Fact(DisplayName = "Every invariant catches at least one planted fault (an invariant that never bit is not trusted)")]
    public void EveryInvariantBites()
    {
        var biters = new HashSet<string>();
        foreach (var fault in PlantedFaults.All)
        {
            var impl = PlantedFaults.Create(fault.Id);
            foreach (var invariant in InvariantCatalogue.All)
            {
                if (invariant.Run(impl, 2000, PropertyRun.SeedFor(invariant.Id)).Status == ResultStatus.Failed)
                {
                    biters.Add(invariant.Id);
                }
            }
        }

        var toothless = InvariantCatalogue.All.Select(i => i.Id).Where(id => !biters.Contains(id)).ToList();
        output.WriteLine("invariants that caught a fault: " + string.Join(", ", biters.Order()));
        Assert.Empty(toothless);
    }

    [Fact(DisplayName = "Every declared catcher of every fault really catches it")]
    public void DeclaredCatchersAreReal()
    {
        foreach (var fault in PlantedFaults.All)
        {
            var impl = PlantedFaults.Create(fault.Id);
            foreach (var id in fault.CaughtBy)
            {
                var result = InvariantCatalogue.Find(id)!.Run(impl, Profile.Pr.CasesPerInvariant, PropertyRun.SeedFor(id));
                Assert.True(result.Status == ResultStatus.Failed, $"{fault.Id} should be caught by {id} but was not");
            }
        }
    }
}
