using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Props.ConformanceChecks;

/// <summary>
/// Issue 53, "only its deviation is excused", for the parts lists: with ace-keeps-stale-cells declared the PARTS-INDOOR
/// invariants ask each walk's parts queries whole (one array per walk and kind, facts §7 #6). CONFORMANCE compares
/// exactly with the declared reference's walk, and SOUNDNESS excuses only the cells of the walk's previous answer: a port
/// that reorders, clears its list per query, or adds a cell the previous answer did not hold fails.
/// </summary>
public sealed class PartsStaleCellsExactTests
{
    private const int Cases = 1_000;

    private static readonly ReferenceAdapter Stale = new(PickPolicy.Retail) { Indoor = new IndoorFidelity(AceKeepsStaleCells: true) };

    [Fact(DisplayName = "PARTS-INDOOR-* (ace-keeps-stale-cells declared): the stale reference passes all four")]
    public void StaleReferencePasses()
    {
        foreach (var invariant in PartsIndoorInvariants.All)
        {
            var result = invariant.Run(Stale, Cases, PropertyRun.SeedFor(invariant.Id));
            Assert.True(result.Status == ResultStatus.Passed, $"{invariant.Id}: {result.Violation?.Message}");
        }
    }

    [Fact(DisplayName = "PARTS-INDOOR-CONFORMANCE (ace-keeps-stale-cells declared): a port that only reorders the parts lists fails")]
    public void ReorderingFails() =>
        Assert.Equal(ResultStatus.Failed, Run(PartsIndoorInvariants.Conformance, new RewrittenAnswers(Stale, RewrittenAnswers.Reversed)));

    [Fact(DisplayName = "PARTS-INDOOR-CONFORMANCE (ace-keeps-stale-cells declared): a port that clears its parts list every query (retail) fails the declaration")]
    public void RetailDeclaringStaleFails() =>
        Assert.Equal(ResultStatus.Failed, Run(PartsIndoorInvariants.Conformance, new RewrittenAnswers(ReferenceAdapter.Instance, r => r) { Declares = Stale.Indoor }));

    [Fact(DisplayName = "PARTS-INDOOR-SOUNDNESS (ace-keeps-stale-cells declared): a far land cell added to a walk's odd answers only (so never held by the previous answer) fails: the declaration excuses only the previous answer's cells")]
    public void ExtraCellNotInThePreviousAnswerFails() =>
        Assert.Equal(ResultStatus.Failed, Run(PartsIndoorInvariants.Soundness, new OddAnswersExtra(Stale)));

    private static ResultStatus Run(Invariant<AcPhys.Formats.Cases.SceneWalk> invariant, ICellPhysics impl) =>
        invariant.Run(impl, Cases, PropertyRun.SeedFor(invariant.Id), maxClasses: 1).Status;

    // The inner port's parts walks with a far land cell appended to answers 1, 3, 5, … of each walk (never to answer 0).
    private sealed class OddAnswersExtra(ICellPhysics inner) : Forwarding(inner), ICellPhysics
    {
        public IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) =>
            [.. Inner.FindCellPartsWalk(scene, queries, loadCells).Select((r, i) => i % 2 == 1 ? RewrittenAnswers.WithExtraCell(r) : r)];
    }
}
