using System.Collections.Concurrent;
using System.Globalization;
using AcPhys.Contract;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Props.Running;

/// <summary>
/// CATALOGUE-JOBS (issue 51): a catalogue run on two threads reports what the run on one thread reports — every
/// invariant's verdict, cases, classes, seeds and shrunk violations, in catalogue order — so <c>verify --jobs</c> never
/// changes a verdict.
/// </summary>
public sealed class ConcurrentCatalogueTests
{
    // A small budget (seconds): every invariant still runs, fails and shrinks where the fault bites.
    private static readonly Profile Small = new("jobs", 25, Profile.Pr.BaseSeed, false);

    [Theory(DisplayName = "CATALOGUE-JOBS: two threads report what one thread does, invariant by invariant (the reference, an indoor and an outdoor planted fault)")]
    [InlineData("reference")]
    [InlineData("building-first-portal-only")]
    [InlineData("trunc-floor")]
    public void TwoThreadsReportWhatOneDoes(string subject)
    {
        ICellPhysics Make() => subject == "reference" ? ReferenceAdapter.Instance : PlantedFaults.Create(subject);
        var one = Make();
        var sequential = CatalogueRunner.RunCatalogue(one, Small, CatalogueWorkers.One);

        var threads = new ConcurrentDictionary<int, byte>();
        var instances = new ConcurrentDictionary<ICellPhysics, byte>(ReferenceEqualityComparer.Instance);
        var first = Make();
        var concurrent = ConcurrentCatalogue.Run(
            [.. InvariantCatalogue.All],
            first,
            new CatalogueWorkers(2, Make),
            (invariant, impl) =>
            {
                threads.TryAdd(Environment.CurrentManagedThreadId, 0);
                instances.TryAdd(impl, 0);
                return CatalogueRunner.RunInvariant(invariant, impl, Small, Small.BaseSeed!.Value);
            },
            null);

        Assert.Equal(2, threads.Count); // both threads judged invariants
        Assert.Equal(subject == "reference" ? 1 : 2, instances.Count); // the reference shared, a fault one instance per thread
        Assert.Equal(sequential.Select(Text), concurrent.Select(Text));
        Assert.Equal(subject == "reference", sequential.All(r => r.Status != ResultStatus.Failed)); // a fault's report has failures to compare
    }

    [Fact(DisplayName = "CATALOGUE-JOBS: progress comes in catalogue order, and an error is the first invariant's in catalogue order, with no progress past it")]
    public void ProgressInOrderAndFirstErrorWins()
    {
        var all = InvariantCatalogue.All.ToList();
        var progress = new List<string>();
        InvariantResult Fake(Invariant invariant, ICellPhysics impl)
        {
            int index = all.IndexOf(invariant);
            Thread.Sleep((index * 7) % 5); // finish out of order
            return index is 5 or 7
                ? throw new InvalidOperationException("error at " + index.ToString(CultureInfo.InvariantCulture))
                : new InvariantResult { Invariant = invariant, Status = ResultStatus.Passed, Seed = new Seed(1, 1) };
        }

        var error = Assert.Throws<InvalidOperationException>(() => ConcurrentCatalogue.Run(all, ReferenceAdapter.Instance, new CatalogueWorkers(3, null), Fake, r => progress.Add(r.Invariant.Id)));
        Assert.Equal("error at 5", error.Message);
        Assert.Equal(all.Take(5).Select(i => i.Id), progress);

        progress.Clear();
        var results = ConcurrentCatalogue.Run(all, ReferenceAdapter.Instance, new CatalogueWorkers(3, null), (i, impl) => new InvariantResult { Invariant = i, Status = ResultStatus.Passed }, r => progress.Add(r.Invariant.Id));
        Assert.Equal(all.Select(i => i.Id), progress);
        Assert.Equal(all.Select(i => i.Id), results.Select(r => r.Invariant.Id));
    }

    // Everything a report prints of a result but its times.
    private static string Text(InvariantResult r) => string.Join(
        " | ",
        r.Invariant.Id,
        r.Status,
        r.Cases,
        r.Applicable,
        r.ExhaustiveCases,
        string.Join(",", r.Classes.OrderBy(c => c.Key, StringComparer.Ordinal).Select(c => c.Key + "=" + c.Value)),
        r.Seed,
        Violation(r.Violation),
        Violation(r.Original),
        r.FailureClass,
        string.Join(",", r.MoreFailures.Select(m => m.Class + ":" + Violation(m.Violation) + "@" + m.Replay)),
        r.Replay,
        r.NotTestedReason);

    private static string Violation(Violation? v) => v is null ? "-" : $"{v} step {v.Step}";
}
