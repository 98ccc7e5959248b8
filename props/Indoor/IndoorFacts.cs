using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>Indoor membership, fact by fact (facts §4, §5, §6.9, §6.11, §7): a two-room cottage in 0xA9B4 at (50, 50).</summary>
public sealed class IndoorFacts
{
    private static readonly CellId Room0 = new(0xA9B40100);
    private static readonly CellId Room1 = new(0xA9B40101);
    private static readonly CellId Owner = new(0xA9B40013); // (50, 50) → cx 2, cy 2

    private static readonly CottagePlan Plan = new((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, false, false);

    private static CellQueryResult Query(CellArray array, CellId position, Vector3 center, CellId current = default, CellQueryOptions? options = null, Scene? scene = null) =>
        SceneQuery.FindCellList(array, SceneBuild.Build(scene ?? SceneKit.Cottage(Plan)), position, [new Sphere(center, 0.5f)], current, options ?? CellQueryOptions.RetailStatic);

    [Fact(DisplayName = "facts §5.3: the building belongs to the land cell under its origin")]
    public void BuildingOwner() => Assert.Equal(Owner, SceneBuild.Build(SceneKit.Cottage(Plan)).Buildings.Keys.Single());

    [Fact(DisplayName = "facts §5.3: a building whose origin lies in another block is discarded at load")]
    public void BuildingInAnotherBlockIsDiscarded()
    {
        var scene = new CellScene([new LandblockId(0xA9B4)], [], [new Building(new LandblockId(0xA9B4), new Vector3(-1, 50, 0), [])]);
        Assert.Empty(scene.Buildings);
        Assert.Single(scene.Discarded);
    }

    [Fact(DisplayName = "INTERIOR-WINS (facts §4 4b): from outdoors, a sphere inside room 0 is picked into room 0 although the land cell contains it too")]
    public void InteriorWins()
    {
        var array = new CellArray();
        var result = Query(array, Owner, new Vector3(53, 51, 0.5f));
        Assert.Equal(Room0, result.Containing);
        Assert.True(result.HitsInteriorCell);
        Assert.True(array.Contains(Owner));
    }

    [Fact(DisplayName = "facts §5.3: a sphere 1 m in front of the door stays outdoors")]
    public void InFrontOfDoorStaysOutside()
    {
        var array = new CellArray();
        var result = Query(array, Owner, new Vector3(53, 49, 0.5f));
        Assert.Equal(Owner, result.Containing);
        Assert.False(array.Contains(Room0));
    }

    [Fact(DisplayName = "facts §5.1, §4 step 5: straddling the exit adds land cells; the filter drops them but the pick may still name one")]
    public void ExitStraddle()
    {
        var array = new CellArray();
        var inside = Query(array, Room0, new Vector3(53, 50.2f, 0.5f));
        Assert.Equal(Room0, inside.Containing);
        Assert.Equal([Room0], array.ToIdArray());

        var past = Query(array, Room0, new Vector3(53, 49.7f, 0.5f));
        Assert.Equal(Owner, past.Containing); // currCell is not re-validated against the filter
        Assert.DoesNotContain(array.ToIdArray(), id => id.IsLand);

        Query(array, Room0, new Vector3(53, 49.7f, 0.5f), options: CellQueryOptions.RetailTransition);
        Assert.Contains(Owner, array.ToIdArray()); // retail transitions do not filter (facts §7 #9)
    }

    [Fact(DisplayName = "facts §6.9: a sphere already wholly past the exit plane triggers nothing: no containing cell")]
    public void WhollyPastExitHasNoCell()
    {
        var array = new CellArray();
        Assert.Equal(CellId.None, Query(array, Room0, new Vector3(53, 49.4f, 0.5f)).Containing);
    }

    [Fact(DisplayName = "facts §5.1: a sphere crossing an inner door is added to the next room, and the seed cell keeps the pick on the shared plane")]
    public void InnerDoor()
    {
        var array = new CellArray();
        var onPlane = Query(array, Room0, new Vector3(56, 53, 0.5f));
        Assert.Equal([Room0, Room1], array.ToIdArray());
        Assert.Equal(Room0, onPlane.Containing); // both contain a point on the plane: the first env hit wins
        var beyond = Query(array, Room0, new Vector3(56.3f, 53, 0.5f));
        Assert.Equal(Room1, beyond.Containing);
    }

    [Fact(DisplayName = "HYSTERESIS: current-first keeps the current room on a shared plane; retail takes the position's room")]
    public void CurrentFirstIndoors()
    {
        var array = new CellArray();
        var p = new Vector3(56, 53, 0.5f);
        Assert.Equal(Room0, Query(array, Room0, p, Room1).Containing);
        Assert.Equal(Room1, Query(array, Room0, p, Room1, CellQueryOptions.RetailStatic with { Policy = PickPolicy.CurrentFirst }).Containing);
    }

    [Theory(DisplayName = "facts §5.1, §5.4: a load hint for an unloaded neighbour appears iff a sphere reaches its side (both PortalSide encodings)")]
    [InlineData(0)]
    [InlineData(-1)]
    public void LoadHintFollowsPortalSide(int flips)
    {
        // Dungeon of 3 cells, 8 m long, the last unloaded: cell 1 spans x ∈ [8, 16] from origin (20, 20) in 0xA9B4.
        var scene = SceneKit.Dungeon(new DungeonPlan((0xA9 * 192.0) + 20, (0xB4 * 192.0) + 20, 3, 8f, 1, flips));
        var cell1 = new CellId(0xA9B40101);
        var hint = new CellId(0xA9B40102);
        var array = new CellArray();
        var near = SceneQuery.FindCellList(array, SceneBuild.Build(scene), cell1, [new Sphere(new Vector3(35.6f, 22, 0.5f), 0.5f)], default, CellQueryOptions.RetailStatic);
        Assert.Contains(new CellEntry(hint, false), Entries(array));
        Assert.Equal(cell1, near.Containing);
        SceneQuery.FindCellList(array, SceneBuild.Build(scene), cell1, [new Sphere(new Vector3(35.4f, 22, 0.5f), 0.5f)], default, CellQueryOptions.RetailStatic);
        Assert.DoesNotContain(hint, array.ToIdArray());
    }

    [Fact(DisplayName = "facts §7 #11: ACE keys a load hint by the bare 16-bit id")]
    public void AceLoadHintKey()
    {
        var scene = SceneKit.Dungeon(new DungeonPlan((0xA9 * 192.0) + 20, (0xB4 * 192.0) + 20, 3, 8f, 1, 0));
        var array = new CellArray();
        var ace = CellQueryOptions.RetailStatic with { Fidelity = new IndoorFidelity(AceLoadHintLowKey: true) };
        SceneQuery.FindCellList(array, SceneBuild.Build(scene), new CellId(0xA9B40101), [new Sphere(new Vector3(35.8f, 22, 0.5f), 0.5f)], default, ace);
        Assert.Contains(new CellId(0x0102), array.ToIdArray());
    }

    [Fact(DisplayName = "facts §6.11: retail does not enter a neighbour block's building from this block's frame; re-framing (not retail) does")]
    public void CrossBlockBuildingEntry()
    {
        // Cottage origin at x = 190 of 0xA9B4; room 0 spans x ∈ [190, 196], i.e. into 0xAAB4.
        var plan = Plan with { WorldX = (0xA9 * 192.0) + 190 };
        var scene = SceneKit.Cottage(plan);
        var east = new CellId(0xAAB40003); // (0.3, 51) in 0xAAB4: cx 0, cy 2
        var owner = new CellId(0xA9B4003B);
        var array = new CellArray();
        var retail = Query(array, east, new Vector3(0.3f, 51, 0.5f), scene: scene);
        Assert.Contains(owner, array.ToIdArray());
        Assert.Equal(east, retail.Containing);

        var fixedOptions = CellQueryOptions.RetailStatic with { Fidelity = new IndoorFidelity(ReframeTransit: true) };
        Assert.Equal(Room0, Query(array, east, new Vector3(0.3f, 51, 0.5f), options: fixedOptions, scene: scene).Containing);

        // Once the check position is framed in the owning block, retail enters.
        Assert.Equal(Room0, Query(array, owner, new Vector3(192.3f, 51, 0.5f), scene: scene).Containing);
    }

    [Fact(DisplayName = "facts §4 step 1, §7 #6: retail truncates the array per call; ACE keeps earlier entries")]
    public void ResetBetweenCalls()
    {
        var array = new CellArray();
        Query(array, Owner, new Vector3(53, 51, 0.5f));
        Query(array, Owner, new Vector3(60, 40, 0.5f));
        Assert.DoesNotContain(Room0, array.ToIdArray());

        var ace = CellQueryOptions.RetailStatic with { Fidelity = new IndoorFidelity(AceKeepsStaleCells: true) };
        Query(array, Owner, new Vector3(53, 51, 0.5f), options: ace);
        Query(array, Owner, new Vector3(60, 40, 0.5f), options: ace);
        Assert.Contains(Room0, array.ToIdArray());
    }

    [Fact(DisplayName = "facts §7 #10: ACE resolves a portal's neighbour through VisibleCells only; retail through every loaded cell")]
    public void AceNeighbourViaVisibleCells()
    {
        var scene = SceneKit.Cottage(Plan);
        var blind = scene with { Cells = [.. scene.Cells.Select(c => c with { Visible = [] })] };
        var array = new CellArray();
        var ace = CellQueryOptions.RetailTransition with { Fidelity = new IndoorFidelity(AceNeighbourViaVisibleCells: true) };
        Query(array, Room0, new Vector3(56.3f, 53, 0.5f), options: ace, scene: blind);
        Assert.Contains(new CellEntry(Room1, false), Entries(array)); // a load hint: room 1 is not in room 0's list
        Query(array, Room0, new Vector3(56.3f, 53, 0.5f), options: CellQueryOptions.RetailTransition, scene: blind);
        Assert.Contains(new CellEntry(Room1, true), Entries(array));
    }

    [Fact(DisplayName = "facts §7 #12: an exit is flag 4 in retail, OtherCellId 0xFFFF in ACE")]
    public void OutsideDetection()
    {
        // Room 0 with one portal: OtherCellId 0xFFFF but flag 4 clear (PortalSide true, the owning cell on the negative side).
        var portal = new CellPortal(CellPortal.FlagsFor(portalSide: true, outside: false), 0, CellPortal.Outside, 0xFFFF, new CellPlane(-Vector3.UnitY, 0));
        var env = new EnvCell(Room0, new Frame(new Vector3(50, 50, 0), System.Numerics.Quaternion.Identity), new CellBsp([ConvexPiece.FromBox(Vector3.Zero, new Vector3(6, 6, 3))]), [portal], []);
        var scene = new CellScene([new LandblockId(0xA9B4)], [env], []);
        var array = new CellArray();
        Sphere[] spheres = [new Sphere(new Vector3(53, 50.2f, 0.5f), 0.5f)];
        SceneQuery.FindCellList(array, scene, Room0, spheres, default, CellQueryOptions.RetailTransition);
        Assert.Equal([Room0, new CellId(0xA9B4FFFF)], array.ToIdArray()); // retail: not an exit; block | 0xFFFF resolves to nothing: a load hint
        var ace = CellQueryOptions.RetailTransition with { Fidelity = new IndoorFidelity(AceOutsideByCellId: true) };
        SceneQuery.FindCellList(array, scene, Room0, spheres, default, ace);
        Assert.Contains(Owner, array.ToIdArray()); // ACE: an exit, the outdoor cells are added
    }

    [Fact(DisplayName = "facts §7 #8: ACE filters outside the (visible && numSphere) guard; seen only with ACE's stale array (#6), where a sphere-less indoor query then drops stale land cells")]
    public void AceFilterOutsideGuard()
    {
        // Alone, #8 cannot be seen: a retail array is reset, so a sphere-less query holds only the position (nothing to filter).
        var built = SceneBuild.Build(SceneKit.Cottage(Plan));
        var cases = new[]
        {
            (Name: "retail", Fidelity: IndoorFidelity.Retail, LandSurvives: false),
            (Name: "ACE #6 only", Fidelity: new IndoorFidelity(AceKeepsStaleCells: true), LandSurvives: true),
            (Name: "ACE #6 + #8", Fidelity: new IndoorFidelity(AceKeepsStaleCells: true, AceFilterOutsideGuard: true), LandSurvives: false),
        };
        foreach (var c in cases)
        {
            var options = CellQueryOptions.RetailStatic with { Fidelity = c.Fidelity };
            var array = new CellArray();
            Query(array, Owner, new Vector3(60, 40, 0.5f), options: options);
            Assert.Contains(array.ToIdArray(), id => id.IsLand); // the outdoor query left land cells
            SceneQuery.FindCellList(array, built, Room0, [], default, options);
            Assert.True(c.LandSurvives == array.ToIdArray().Any(id => id.IsLand), $"{c.Name}: land cells {(c.LandSurvives ? "should" : "should not")} survive: [{string.Join(", ", array.ToIdArray())}]");
            Assert.Contains(Room0, array.ToIdArray());
        }
    }

    [Fact(DisplayName = "facts §7 #7: ACE's early return after an interior pick skips the filter; retail filters")]
    public void AceEarlyReturnSkipsFilter()
    {
        var array = new CellArray();
        var ace = CellQueryOptions.RetailStatic with { Fidelity = new IndoorFidelity(AceEarlyReturn: true) };
        Query(array, Room0, new Vector3(53, 50.2f, 0.5f), options: ace);
        Assert.Contains(array.ToIdArray(), id => id.IsLand);
        Query(array, Room0, new Vector3(53, 50.2f, 0.5f));
        Assert.DoesNotContain(array.ToIdArray(), id => id.IsLand);
    }

    [Fact(DisplayName = "facts §4 step 5: the filter removes env cells the starting cell does not see")]
    public void FilterUsesVisibleCells()
    {
        var scene = SceneKit.Cottage(Plan);
        var blind = scene with { Cells = [.. scene.Cells.Select(c => c with { Visible = [] })] };
        var array = new CellArray();
        Query(array, Room0, new Vector3(56, 53, 0.5f), scene: blind);
        Assert.Equal([Room0], array.ToIdArray());
    }

    [Fact(DisplayName = "facts §7 #13: retail's point_in_cell is false for a cell without portals; ACE's is not")]
    public void NoPortalGuard()
    {
        var cell = new SceneCell(Room0, new Vector3(50, 50, 0), Quaternion.Identity, [ScenePiece.FromBox(Vector3.Zero, new Vector3(6, 6, 3))], [], []);
        var env = SceneBuild.Cell(cell, VolumeMode.Bsp);
        Assert.False(env.PointInCell(new Vector3(53, 53, 1), IndoorFidelity.Retail));
        Assert.True(env.PointInCell(new Vector3(53, 53, 1), new IndoorFidelity(AceNoPortalGuard: true)));
    }

    [Fact(DisplayName = "An unloaded block's cells are load hints, never a crash; no loaded cell contains the centre ⇒ no containing cell")]
    public void UnloadedNeighbourBlock()
    {
        var scene = SceneKit.Cottage(Plan with { LoadNeighbours = false });
        var array = new CellArray();
        var west = Query(array, new CellId(0xA9B40001), new Vector3(-0.5f, 10, 0.5f), scene: scene);
        Assert.Equal(CellId.None, west.Containing);
        Assert.Contains(new CellEntry(new CellId(0xA8B40039), false), Entries(array));
    }

    [Fact(DisplayName = "Hot path: find_cell_list over a scene does not allocate once the array has grown")]
    public void DoesNotAllocate()
    {
        var built = SceneBuild.Build(SceneKit.Cottage(Plan));
        var array = new CellArray();
        Sphere[] spheres = [new Sphere(new Vector3(53, 50.2f, 0.5f), 0.5f), new Sphere(new Vector3(53, 50.2f, 1.3f), 0.5f)];
        for (int i = 0; i < 3; i++)
        {
            SceneQuery.FindCellList(array, built, Room0, spheres, Room0, CellQueryOptions.RetailStatic);
            SceneQuery.FindCellList(array, built, Owner, spheres, Owner, CellQueryOptions.RetailTransition);
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            SceneQuery.FindCellList(array, built, Room0, spheres, Room0, CellQueryOptions.RetailStatic);
            SceneQuery.FindCellList(array, built, Owner, spheres, Owner, CellQueryOptions.RetailTransition);
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    private static CellEntry[] Entries(CellArray array) => [.. Enumerable.Range(0, array.Count).Select(i => array[i])];
}
