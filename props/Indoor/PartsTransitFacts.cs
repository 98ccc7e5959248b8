using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>The parts variants of env transit and building entry (facts §5.2, §5.3, §7 #14) on the two-room cottage in 0xA9B4.</summary>
public sealed class PartsTransitFacts
{
    private static readonly CellId Room0 = new(0xA9B40100);
    private static readonly CellId Room1 = new(0xA9B40101);
    private static readonly CellId Owner = new(0xA9B40013);
    private static readonly CellScene Scene = SceneBuild.Build(SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, false, false)));

    private static Part At(float x, float y) => new(Owner, new Frame(new Vector3(x, y, 1), Quaternion.Identity), new Box(new Vector3(-0.2f), new Vector3(0.2f)), 0.5f, false);

    [Fact(DisplayName = "facts §5.7: intersect_box is Crossing within EPS of Min and when corners differ; else the common side")]
    public void IntersectBox()
    {
        var plane = new CellPlane(Vector3.UnitX, -1);
        Assert.Equal(Sidedness.Positive, BoxSide.Of(plane, new Box(new Vector3(2, 0, 0), new Vector3(3, 1, 1))));
        Assert.Equal(Sidedness.Negative, BoxSide.Of(plane, new Box(new Vector3(-1, 0, 0), new Vector3(0, 1, 1))));
        Assert.Equal(Sidedness.Crossing, BoxSide.Of(plane, new Box(new Vector3(0, 0, 0), new Vector3(2, 1, 1))));
        Assert.Equal(Sidedness.Crossing, BoxSide.Of(plane, new Box(new Vector3(1.0001f, 0, 0), new Vector3(2, 1, 1)))); // d(Min) within EPS
    }

    [Fact(DisplayName = "facts §5.2: a part straddling an inner door adds the next room; one deep inside adds nothing")]
    public void InnerDoor()
    {
        var array = new CellArray();
        var env = Scene.GetEnvCell(Room0)!;
        EnvTransitParts.FindTransitCells(array, Scene, env, [At(55.9f, 53)], IndoorFidelity.Retail);
        Assert.Equal([Room1], array.ToIdArray());
        array.Reset();
        EnvTransitParts.FindTransitCells(array, Scene, env, [At(53, 53)], IndoorFidelity.Retail);
        Assert.Equal(0, array.Count);
    }

    [Fact(DisplayName = "facts §5.2: a part straddling the exit adds the land cells through the parts variant, called for the cell")]
    public void Exit()
    {
        var array = new CellArray();
        EnvTransitParts.FindTransitCells(array, Scene, Scene.GetEnvCell(Room0)!, [At(53, 50.1f)], IndoorFidelity.Retail);
        Assert.Contains(Owner, array.ToIdArray());
    }

    [Fact(DisplayName = "facts §5.3, §7 #14: entering by parts, retail accepts a box on the cell's side of the door, ACE the opposite side; both accept Crossing")]
    public void BuildingEntryBoxSide()
    {
        var env = Scene.GetEnvCell(Room0)!;
        var array = new CellArray();
        Assert.True(EnvTransitParts.CheckBuildingTransit(array, Scene, env, 0, [At(53, 50.3f)], IndoorFidelity.Retail));
        Assert.Contains(Room0, array.ToIdArray());
        array.Reset();
        Assert.False(EnvTransitParts.CheckBuildingTransit(array, Scene, env, 0, [At(53, 50.3f)], IndoorFidelity.Retail with { AceBoxSidePairing = true }));
        array.Reset();
        Assert.True(EnvTransitParts.CheckBuildingTransit(array, Scene, env, 0, [At(53, 50.05f)], IndoorFidelity.Retail with { AceBoxSidePairing = true }));
        array.Reset();
        Assert.False(EnvTransitParts.CheckBuildingTransit(array, Scene, env, 0xFFFF, [At(53, 50.05f)], IndoorFidelity.Retail));
        Assert.Equal(0, array.Count);
    }

    [Fact(DisplayName = "facts §5.3, §3.4, §7 #3: a room entered by parts exits with the declared outdoor parts rules: retail adds the cell across the block line, ACE's same-block guard does not")]
    public void BuildingEntryExitsWithTheDeclaredPartsRules()
    {
        // The anchor straddles the cottage's door (crossing: both pairings enter); a second part, in the anchor's block
        // frame at y = 200, stretches the add_cell_block range into 0xA9B5's row 0 (column 2: low 0x11).
        Part[] parts = [At(53, 50.1f), At(53, 200)];
        var across = new CellId(0xA9B50011);
        var env = Scene.GetEnvCell(Room0)!;
        var retail = new CellArray();
        Assert.True(EnvTransitParts.CheckBuildingTransit(retail, Scene, env, 0, parts, IndoorFidelity.Retail, PartsFidelity.Retail));
        Assert.Contains(across, retail.ToIdArray());
        Assert.Contains(Owner, retail.ToIdArray());
        var ace = new CellArray();
        Assert.True(EnvTransitParts.CheckBuildingTransit(ace, Scene, env, 0, parts, IndoorFidelity.Retail, PartsFidelity.Ace));
        Assert.DoesNotContain(across, ace.ToIdArray());
        Assert.Contains(Owner, ace.ToIdArray());
    }
}
