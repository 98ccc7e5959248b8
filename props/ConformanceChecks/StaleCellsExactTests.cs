using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.ConformanceChecks;

/// <summary>
/// Issue 41, "only its deviation is excused": with ace-keeps-stale-cells declared, FIND-CELL-CONFORMANCE compares
/// exactly with the declared reference asked the walk's queries in the order the port was asked them (one array per
/// walk, facts §7 #6), no longer as sets. A port that reorders candidates, adds a cell no query of the walk answered, or
/// clears its array per query fails under that declaration.
/// </summary>
public sealed class StaleCellsExactTests
{
    private const int Cases = 2_000;

    private static readonly ReferenceAdapter Stale = new(PickPolicy.Retail) { Indoor = new IndoorFidelity(AceKeepsStaleCells: true) };

    private static Seed SeedOf => PropertyRun.SeedFor("FIND-CELL-CONFORMANCE");

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE (ace-keeps-stale-cells declared): the stale reference passes, and its walks do differ from retail's (the declaration is exercised)")]
    public void StaleReferencePassesAndDiffersFromRetail()
    {
        Assert.Equal(ResultStatus.Passed, ConformanceInvariants.FindCell.Run(Stale, Cases, SeedOf).Status);
        int differing = 0;
        foreach (var w in StaleWalks(200))
        {
            var stale = Stale.FindCellWalk(w);
            var retail = ReferenceAdapter.Instance.FindCellWalk(w);
            differing += stale.Zip(retail).Any(p => Conformance.Difference(p.First, p.Second) is not null) ? 1 : 0;
        }

        Assert.True(differing > 0, "no generated scene walk keeps a stale cell: the exact comparison would be untested");
    }

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE (ace-keeps-stale-cells declared): a port that only reorders the candidates fails")]
    public void ReorderingFails() =>
        Assert.Equal(ResultStatus.Failed, ConformanceInvariants.FindCell.Run(new RewrittenAnswers(Stale, RewrittenAnswers.Reversed), Cases, SeedOf, maxClasses: 1).Status);

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE (ace-keeps-stale-cells declared): a port that only adds a cell no query of the walk answered fails")]
    public void AddingANonStaleCellFails() =>
        Assert.Equal(ResultStatus.Failed, ConformanceInvariants.FindCell.Run(new RewrittenAnswers(Stale, RewrittenAnswers.WithExtraCell), Cases, SeedOf, maxClasses: 1).Status);

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE (ace-keeps-stale-cells declared): a port that clears its array every query (retail) fails the declaration")]
    public void RetailDeclaringStaleFails() =>
        Assert.Equal(ResultStatus.Failed, ConformanceInvariants.FindCell.Run(new RewrittenAnswers(ReferenceAdapter.Instance, r => r) { Declares = Stale.Indoor }, Cases, SeedOf, maxClasses: 1).Status);

    private static IEnumerable<WalkRequest> StaleWalks(int count) =>
        Gen.Sample(SceneGens.Recipes.Select(r => r.Build()), count, new Rnd(41, 0x9E3779B97F4A7C15UL), 50).Select(w => WalkRunner.Request(w.Walk, w.Scene));
}
