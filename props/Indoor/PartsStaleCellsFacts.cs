using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>
/// The reference's parts lists under ace-keeps-stale-cells (issue 53; facts §3.5, §4 step 1, §7 #6): ACE's
/// find_bbox_cell_list resets only the AddedOutside latch, so one walk's parts queries of one kind share one array —
/// never cleared within the walk, empty at its start — while a single parts query starts empty.
/// </summary>
public sealed class PartsStaleCellsFacts(ITestOutputHelper output)
{
    private const int Cases = 300;

    private static readonly ReferenceAdapter Stale = new(PickPolicy.Retail) { Indoor = new IndoorFidelity(AceKeepsStaleCells: true) };

    [Fact(DisplayName = "facts §7 #6 parts: a single parts query under ace-keeps-stale-cells is retail's (its array starts empty), and so is a walk's first answer")]
    public void SingleQueryAndFirstAnswerAreRetail()
    {
        int walks = 0;
        Each((w, queries, loadCells) =>
        {
            var walk = Stale.FindCellPartsWalk(w.Scene, queries, loadCells);
            var first = ReferenceAdapter.Instance.FindCellParts(w.Scene, queries[0], loadCells);
            Assert.Equal(first.Cells, walk[0].Cells);
            Assert.Equal(first.Loaded, walk[0].Loaded);
            foreach (var parts in queries)
            {
                Assert.Equal(ReferenceAdapter.Instance.FindCellParts(w.Scene, parts, loadCells).Cells, Stale.FindCellParts(w.Scene, parts, loadCells).Cells);
            }

            walks++;
        });
        Assert.True(walks > 0);
    }

    [Fact(DisplayName = "facts §7 #6 parts: as a transition (no filter) each answer keeps every cell of the walk's previous answer and holds every cell of retail's answer; some walks differ from retail (counts printed)")]
    public void TransitionAnswersKeepThePreviousCells()
    {
        int walks = 0, differing = 0, kept = 0;
        Each((w, queries, loadCells) =>
        {
            if (!loadCells)
            {
                return;
            }

            var walk = Stale.FindCellPartsWalk(w.Scene, queries, true);
            bool differs = false;
            for (int i = 0; i < queries.Count; i++)
            {
                var retail = ReferenceAdapter.Instance.FindCellParts(w.Scene, queries[i], true).Cells;
                Assert.Empty(retail.Except(walk[i].Cells));
                if (i > 0)
                {
                    Assert.Empty(walk[i - 1].Cells.Except(walk[i].Cells));
                    kept += walk[i - 1].Cells.Except(retail).Count();
                }

                differs |= !retail.SequenceEqual(walk[i].Cells);
            }

            walks++;
            differing += differs ? 1 : 0;
        });
        output.WriteLine($"{walks} transition parts walks, {differing} differ from retail, {kept} stale cells kept");
        Assert.True(differing > 0, "no parts walk keeps a stale cell: the declaration would be untested");
    }

    [Fact(DisplayName = "facts §7 #6 parts: the stale array lives for one walk: the shared reference, asked every walk before, answers a walk as a fresh one does")]
    public void ArrayLivesForOneWalk()
    {
        int walks = 0;
        Each((w, queries, loadCells) =>
        {
            var fresh = new ReferenceAdapter(PickPolicy.Retail) { Indoor = Stale.Indoor }.FindCellPartsWalk(w.Scene, queries, loadCells);
            var shared = Stale.FindCellPartsWalk(w.Scene, queries, loadCells);
            Assert.Equal(fresh.Select(a => string.Join(",", a.Cells)), shared.Select(a => string.Join(",", a.Cells)));
            walks++;
        });
        Assert.True(walks > 0);
    }

    [Fact(DisplayName = "parts-stale-cleared: the planted fault declares ace-keeps-stale-cells and answers each parts query of a walk as retail does (cleared)")]
    public void ClearedFaultIsRetailPerQuery()
    {
        var fault = PlantedFaults.Create("parts-stale-cleared");
        Assert.True(fault.Indoor.AceKeepsStaleCells);
        Each((w, queries, loadCells) =>
        {
            var got = fault.FindCellPartsWalk(w.Scene, queries, loadCells);
            for (int i = 0; i < queries.Count; i++)
            {
                Assert.Equal(ReferenceAdapter.Instance.FindCellParts(w.Scene, queries[i], loadCells).Cells, got[i].Cells);
            }
        });
    }

    // Every pr case of the parts domain, both kinds: the walk's parts queries as PartsSession asks them.
    private static void Each(Action<SceneWalk, IReadOnlyList<IReadOnlyList<Part>>, bool> visit)
    {
        var judge = PartsIndoorInvariants.Conformance;
        CaseSweep.Each(judge.Domain, Cases, Seed.Derive(Profile.Pr.BaseSeed!.Value, judge.Id), w =>
        {
            var queries = ScenePartsQueries.Of(w).Select(q => (IReadOnlyList<Part>)q.Parts).ToArray();
            if (queries.Length > 0)
            {
                visit(w, queries, false);
                visit(w, queries, true);
            }

            return true;
        });
    }
}
