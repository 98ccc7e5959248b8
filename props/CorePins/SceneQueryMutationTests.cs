using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Mutation;

/// <summary>
/// find_cell_list's own bookkeeping (facts §4), which the scene invariants observe only through the pick: the
/// HitsInteriorCell output, the visible guard of step 2, the stale-array walk of ACE, the early-return filter skip,
/// current-first over a current cell the array does not hold, and a scene's unloaded blocks. One cottage: origin
/// (50, 50) in block A9B4, two 6 × 6 × 3 m rooms along +x (0x100: x 50–56, 0x101: x 56–62), front door the plane y = 50.
/// </summary>
public sealed class SceneQueryMutationTests
{
    private static readonly CellId Room0 = new(0xA9B40100);
    private static readonly CellId Room1 = new(0xA9B40101);
    private static readonly CellId Owner = LandCellAt(Room0, 50, 50);
    private static readonly CellScene Cottage = SceneBuild.Build(SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, false, false)));
    private static readonly CellQueryOptions Transition = CellQueryOptions.RetailTransition; // pick on, filter off

    [Fact(DisplayName = "facts §4 step 3–4: outdoors with no building touched, find_cell_list picks the land cell and leaves HitsInteriorCell false")]
    public void FindCellList_OutdoorsAwayFromBuildingsHitsNoInterior()
    {
        var centre = new Vector3(100, 100, 1);
        var position = LandCellAt(Room0, centre.X, centre.Y);
        var result = SceneQuery.FindCellList(new CellArray(), Cottage, position, [new Sphere(centre, 0.5f)], CellId.None, Transition);
        Assert.Equal(new CellQueryResult(position, false), result);
    }

    [Fact(DisplayName = "facts §4 step 3: an indoor position sets HitsInteriorCell at the seed, with or without a pick, and a pick that finds no cell does not clear it")]
    public void FindCellList_IndoorSeedSetsHitsInterior()
    {
        Sphere[] inside = [new Sphere(new Vector3(52.5f, 53, 1.5f), 0.5f)];
        Assert.Equal(new CellQueryResult(CellId.None, true), SceneQuery.FindCellList(new CellArray(), Cottage, Room0, inside, CellId.None, Transition with { Pick = false }));
        Assert.Equal(new CellQueryResult(Room0, true), SceneQuery.FindCellList(new CellArray(), Cottage, Room0, inside, CellId.None, Transition));

        // The check position still names room 0, but the centre is 40 m away: nothing contains it.
        Sphere[] away = [new Sphere(new Vector3(100, 100, 1), 0.5f)];
        Assert.Equal(new CellQueryResult(CellId.None, true), SceneQuery.FindCellList(new CellArray(), Cottage, Room0, away, CellId.None, Transition));
    }

    [Fact(DisplayName = "facts §5.3: a sphere outside the front door that reaches into room 0 enters it (HitsInteriorCell) while the centre's land cell is still the pick")]
    public void FindCellList_BuildingEntrySetsHitsInteriorWithoutAnInteriorPick()
    {
        var array = new CellArray();
        var result = SceneQuery.FindCellList(array, Cottage, Owner, [new Sphere(new Vector3(53, 49.8f, 1), 0.5f)], CellId.None, Transition);
        Assert.Equal(new CellQueryResult(Owner, true), result);
        Assert.True(array.Contains(Room0), "room 0 is in the array");
    }

    [Fact(DisplayName = "facts §4 step 2: a land position in an unloaded block has no visible cell, so there is no transit and no pick even when the centre lies in a loaded neighbour")]
    public void FindCellList_UnloadedPositionPicksNothing()
    {
        var loaded = Room0.Landblock;
        var scene = new CellScene([loaded], [], []);
        var west = LandCellAt(new LandblockId((byte)(loaded.X - 1), loaded.Y).BlockCell, 180, 100); // the block west of A9B4
        var centre = new Vector3(193, 100, 1); // 1 m into A9B4
        var array = new CellArray();
        var result = SceneQuery.FindCellList(array, scene, west, [new Sphere(centre, 0.5f)], CellId.None, Transition);
        Assert.Equal(new CellQueryResult(CellId.None, false), result);

        // The same centre posed from A9B4's own frame is picked: the guard, not the geometry, decided.
        var own = LandCellAt(Room0, 1, 100);
        Assert.Equal(own, SceneQuery.FindCellList(new CellArray(), scene, own, [new Sphere(centre - new Vector3(192, 0, 0), 0.5f)], CellId.None, Transition).Containing);
    }

    [Fact(DisplayName = "facts §4 step 2, §7 #6: a position whose low word is neither land nor indoor (0x0041–0x00FF, 0) has no visible cell: with ACE's stale array, a stale land cell holding the centre is still not picked")]
    public void FindCellList_OutOfRangeLowWordPicksNothingEvenWithStaleCells()
    {
        var ace = Transition with { Fidelity = new IndoorFidelity(AceKeepsStaleCells: true) };
        Sphere[] spheres = [new Sphere(new Vector3(100, 100, 1), 0.5f)];
        var land = LandCellAt(Room0, 100, 100);
        foreach (ushort low in new ushort[] { 0x0041, 0x0080, 0x00FF, 0x0000 })
        {
            var array = new CellArray();
            Assert.Equal(land, SceneQuery.FindCellList(array, Cottage, land, spheres, CellId.None, ace).Containing); // leaves land cells behind
            var result = SceneQuery.FindCellList(array, Cottage, Room0.WithLow(low), spheres, CellId.None, ace);
            Assert.Equal(new CellQueryResult(CellId.None, false), result);
            Assert.True(array.Contains(land), $"low 0x{low:X4}: the stale land cell is kept (ACE)");
        }
    }

    [Fact(DisplayName = "facts §4 step 4a, §7 #6: with ACE's stale array, a stale land cell's transit runs add_all_outside_cells for the current (indoor) position: the land under room 0 joins")]
    public void FindCellList_StaleLandCellTransitAddsTheCurrentColumn()
    {
        var ace = Transition with { Fidelity = new IndoorFidelity(AceKeepsStaleCells: true) };
        var far = LandCellAt(Room0, 150, 150);
        var array = new CellArray();
        SceneQuery.FindCellList(array, Cottage, far, [new Sphere(new Vector3(150, 150, 1), 0.5f)], CellId.None, ace);
        Assert.False(array.Contains(Owner));

        var result = SceneQuery.FindCellList(array, Cottage, Room0, [new Sphere(new Vector3(52.5f, 53, 1.5f), 0.5f)], CellId.None, ace);
        Assert.Equal(new CellQueryResult(Room0, true), result);
        Assert.True(array.Contains(far), "stale");
        Assert.True(array.Contains(Owner), "the land under room 0, added by the stale land cell's transit");
    }

    [Fact(DisplayName = "facts §4 step 5, §7 #8: without a pick there is no interior pick, so ACE's early return does not skip the indoor filter: the land cells an exit added are dropped")]
    public void FindCellList_NoPickStillFiltersUnderAceEarlyReturn()
    {
        var options = new CellQueryOptions(PickPolicy.Retail, Pick: false, LoadCells: false, new IndoorFidelity(AceEarlyReturn: true));
        Sphere[] atDoor = [new Sphere(new Vector3(53, 50.2f, 1), 0.5f)];
        var unfiltered = new CellArray();
        SceneQuery.FindCellList(unfiltered, Cottage, Room0, atDoor, CellId.None, options with { LoadCells = true });
        Assert.Contains(unfiltered.ToIdArray(), id => id.IsLand); // the exit fired

        var array = new CellArray();
        SceneQuery.FindCellList(array, Cottage, Room0, atDoor, CellId.None, options);
        Assert.DoesNotContain(array.ToIdArray(), id => id.IsLand);
        Assert.Contains(Room0, array.ToIdArray());
    }

    [Fact(DisplayName = "facts §4 step 4a: a load hint is never walked, even one ACE made for a cell the scene holds (a neighbour missing from VisibleCells)")]
    public void FindCellList_LoadHintsAreNotWalked()
    {
        // Room 0 lists no visible cells, so ACE resolves its door to room 1 as a hint; the sphere also straddles
        // room 1's back door plane (y = 56), which would bring the land in if room 1 were walked.
        var plan = new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, true, false);
        var full = SceneBuild.Build(SceneKit.Cottage(plan));
        var room0 = full.GetEnvCell(Room0)!;
        var blind = new EnvCell(Room0, room0.Frame, room0.Volume, room0.Portals.ToArray(), []);
        var scene = new CellScene([Room0.Landblock], [blind, full.GetEnvCell(Room1)!], full.Buildings.Values);
        var options = new CellQueryOptions(PickPolicy.Retail, Pick: false, LoadCells: true, new IndoorFidelity(AceNeighbourViaVisibleCells: true));
        Sphere[] corner = [new Sphere(new Vector3(55.9f, 55.9f, 1), 0.5f)];

        var array = new CellArray();
        SceneQuery.FindCellList(array, scene, Room0, corner, CellId.None, options);
        Assert.Equal([new CellEntry(Room0, true), new CellEntry(Room1, false)], CellArrays.Entries(array));

        // The same query with room 1 visible walks it, and its back door lets the land in.
        var seen = new CellScene([Room0.Landblock], [room0, full.GetEnvCell(Room1)!], full.Buildings.Values);
        var walked = new CellArray();
        SceneQuery.FindCellList(walked, seen, Room0, corner, CellId.None, options);
        Assert.Contains(walked.ToIdArray(), id => id.IsLand);
    }

    [Fact(DisplayName = "facts §4 step 4b (current-first): a current cell the array does not hold is ignored, and the ordinary pick is made")]
    public void PickContaining_CurrentNotInTheArrayIsIgnored()
    {
        var array = new CellArray();
        array.Add(Owner, true);
        var options = Transition with { Policy = PickPolicy.CurrentFirst };
        var pick = SceneQuery.PickContaining(array, Cottage, Owner, new Vector3(60, 60, 0), Room1, options, out bool interior);
        Assert.Equal(Owner, pick);
        Assert.False(interior);
    }

    [Fact(DisplayName = "facts §4 step 4b (current-first): a current env cell that still contains the centre is kept and reported as an interior pick")]
    public void PickContaining_CurrentEnvCellIsAnInteriorPick()
    {
        var array = new CellArray();
        array.Add(Owner, true);
        array.Add(Room1, true);
        array.Add(Room0, true);
        var options = Transition with { Policy = PickPolicy.CurrentFirst };
        var pick = SceneQuery.PickContaining(array, Cottage, Owner, new Vector3(55.5f, 53, 1), Room0, options, out bool interior);
        Assert.Equal(Room0, pick);
        Assert.True(interior);
    }

    [Fact(DisplayName = "facts §4 step 2, §5.3: a scene answers an env cell or a building only while its block is loaded; declared in an unloaded block, both are absent")]
    public void CellScene_LookupsNeedTheBlockLoaded()
    {
        var cells = new[] { Cottage.GetEnvCell(Room0)!, Cottage.GetEnvCell(Room1)! };
        var elsewhere = new LandblockId(0x10, 0x10);
        var unloaded = new CellScene([elsewhere], cells, Cottage.Buildings.Values);
        Assert.Null(unloaded.GetEnvCell(Room0));
        Assert.Null(unloaded.GetBuilding(Owner));
        Assert.Null(unloaded.GetEnvCell(elsewhere.BlockCell.WithLow(0x100))); // loaded, but never declared

        var loaded = new CellScene([Room0.Landblock], cells, Cottage.Buildings.Values);
        Assert.Same(cells[0], loaded.GetEnvCell(Room0));
        Assert.NotNull(loaded.GetBuilding(Owner));
    }

    // The land cell of `block`'s id whose 24 m square holds the block-frame point (x, y), by the facts' arithmetic (§1.2).
    internal static CellId LandCellAt(CellId block, float x, float y) =>
        block.WithLow((ushort)((((int)(x / 24)) * 8) + (int)(y / 24) + 1));
}
