using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The parts cell list's own bookkeeping (core ScenePartsQuery, facts §4 step 1, §7 #6) that no invariant reaches: the
/// protocol never sends an empty parts list, and the reference adapter answers each parts query with a fresh array. The
/// two mutants Stryker left without coverage on 2026-12-06 (lines 29 and 38) are killed here. Same cottage as
/// SceneQueryMutationTests: block A9B4, two 6 × 6 × 3 m rooms from (50, 50), front door the plane y = 50.
/// </summary>
public sealed class ScenePartsQueryMutationTests
{
    private static readonly CellId Room0 = new(0xA9B40100);
    private static readonly CellScene Cottage = SceneBuild.Build(SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, false, false)));
    private static readonly IndoorFidelity Stale = new(AceKeepsStaleCells: true);

    [Fact(DisplayName = "facts §4 step 1: an empty parts list empties the array and hits no interior cell")]
    public void EmptyPartsHitNothing()
    {
        var array = new CellArray();
        Assert.True(ScenePartsQuery.FindCellList(array, Cottage, [PartAt(Room0, 53, 53)], false, default));
        Assert.NotEqual(0, array.Count);

        Assert.False(ScenePartsQuery.FindCellList(array, Cottage, ReadOnlySpan<Part>.Empty, false, default));
        Assert.Equal(0, array.Count);
    }

    [Fact(DisplayName = "facts §7 #6: with ACE's stale array each parts call still clears the outside latch, so a second outdoor call adds its own land cells")]
    public void StaleArrayClearsTheOutsideLatch()
    {
        var first = PartAt(SceneQueryMutationTests.LandCellAt(Room0, 100, 100), 100, 100);
        var second = PartAt(SceneQueryMutationTests.LandCellAt(Room0, 150, 150), 150, 150);
        var fresh = new CellArray();
        ScenePartsQuery.FindCellList(fresh, Cottage, [second], true, Stale);
        var expected = fresh.ToIdArray();
        Assert.Contains(second.Cell, expected);

        var stale = new CellArray();
        ScenePartsQuery.FindCellList(stale, Cottage, [first], true, Stale);
        Assert.Contains(first.Cell, stale.ToIdArray());
        ScenePartsQuery.FindCellList(stale, Cottage, [second], true, Stale);
        var kept = stale.ToIdArray();
        Assert.All(expected, id => Assert.Contains(id, kept));
        Assert.Contains(first.Cell, kept); // the stale entry ACE keeps (§7 #6)
    }

    private static Part PartAt(CellId cell, float x, float y) =>
        new(cell, new Frame(new Vector3(x, y, 1), Quaternion.Identity), new Box(new Vector3(-0.2f), new Vector3(0.2f)), 0.5f, false);
}
