using AcPhys.Contract;
using AcPhys.Props.Indoor;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Land;

/// <summary>
/// Proof that every invariant bites: each catches at least one planted fault. That every fault is caught by the
/// invariants it names is checked per known-bug catalogue entry (props/Bite/KnownBugCatalogueTests.cs). The exact
/// indoor invariants also count their concrete bites with test adapters (props/Indoor/ExactBites.cs).
/// </summary>
public sealed class PlantedFaultsAreCaught(ITestOutputHelper output)
{
    [Fact(DisplayName = "Every invariant catches at least one planted fault (an invariant that never bit is not trusted)")]
    public void EveryInvariantBites()
    {
        var biters = new HashSet<string>();
        var firstBite = new List<string>();
        var faults = PlantedFaults.All;
        var impls = new Dictionary<string, ICellPhysics>(StringComparer.Ordinal);
        foreach (var invariant in InvariantCatalogue.All)
        {
            // One real bite is all this test asks (which faults each invariant catches is the known-bug catalogue's
            // test): the faults that declare the invariant a catcher are tried first, then every other fault, and the
            // first failed run ends the search — the passing runs of invariants that had already bitten were most of
            // this test's time.
            foreach (var fault in faults.OrderBy(f => f.CaughtBy.Contains(invariant.Id) ? 0 : 1))
            {
                if (!impls.TryGetValue(fault.Id, out var impl))
                {
                    impls[fault.Id] = impl = PlantedFaults.Create(fault.Id);
                }

                if (invariant.Run(impl, 2000, PropertyRun.SeedFor(invariant.Id), maxClasses: 1).Status == ResultStatus.Failed)
                {
                    biters.Add(invariant.Id);
                    firstBite.Add(invariant.Id + " by " + fault.Id);
                    break;
                }
            }
        }

        // Invariants whose bites are shown on concrete scenes by test adapters (props/Indoor/ExactBites.cs), not by planted faults.
        foreach (var bite in ExactBites.All)
        {
            if (bite.Invariant.Check(bite.Defect, bite.Case).IsViolation)
            {
                biters.Add(bite.Invariant.Id);
            }
        }

        var toothless = InvariantCatalogue.All.Select(i => i.Id).Where(id => !biters.Contains(id)).ToList();
        output.WriteLine("invariants that caught a fault (the first fault that bit): " + string.Join(", ", firstBite));
        Assert.Empty(toothless);
    }
}
