using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>The indoor benchmark cases (bench/, <c>acphys bench</c>) are hot paths: 0 bytes per query in both volume modes.</summary>
public sealed class IndoorHotPath
{
    public static TheoryData<string, VolumeMode> Cases()
    {
        var data = new TheoryData<string, VolumeMode>();
        foreach (var c in IndoorBenchCases.All)
        {
            data.Add(c.Key, VolumeMode.Bsp);
            data.Add(c.Key, VolumeMode.Aabb);
        }

        return data;
    }

    [Theory(DisplayName = "Hot path: every indoor bench case, BSP and AABB cells, runs find_cell_list without allocating once the array has grown")]
    [MemberData(nameof(Cases))]
    public void DoesNotAllocate(string key, VolumeMode mode)
    {
        var c = IndoorBenchCases.All.Single(x => x.Key == key);
        var scene = SceneBuild.Build(c.Description, mode);
        var array = new CellArray();
        for (int i = 0; i < 3; i++)
        {
            SceneQuery.FindCellList(array, scene, c.Position, c.Spheres, c.Position, c.Options);
        }

        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 0; i < 100; i++)
        {
            SceneQuery.FindCellList(array, scene, c.Position, c.Spheres, c.Position, c.Options);
        }

        Assert.Equal(0, GC.GetAllocatedBytesForCurrentThread() - before);
    }

    [Fact(DisplayName = "The indoor bench cases answer as designed: a room, an L arm BSP leaves out, a door straddle with both rooms, a building entry")]
    public void CasesMeanWhatTheySay()
    {
        var plan = IndoorBenchCases.Plan;
        CellId Pick(string key, VolumeMode mode, out CellArray array)
        {
            var c = IndoorBenchCases.All.Single(x => x.Key == key);
            array = new CellArray();
            return SceneQuery.FindCellList(array, SceneBuild.Build(c.Description, mode), c.Position, c.Spheres, c.Position, c.Options).Containing;
        }

        Assert.Equal(plan.RoomId(1), Pick("box-cottage: inside room 1 (centre)", VolumeMode.Bsp, out _));
        Assert.Equal(CellId.None, Pick("union-cottage: in room 0's second L arm (BSP: outside)", VolumeMode.Bsp, out _));
        Assert.Equal(plan.RoomId(0), Pick("union-cottage: in room 0's second L arm (BSP: outside)", VolumeMode.Aabb, out _));
        Pick("box-cottage: straddling the door to room 1, from room 0", VolumeMode.Bsp, out var door);
        Assert.True(door.Contains(plan.RoomId(0)) && door.Contains(plan.RoomId(1)));
        Pick("box-cottage: outdoors touching the front door (enters room 0)", VolumeMode.Bsp, out var entry);
        Assert.True(entry.Contains(plan.RoomId(0)));
        Pick("box-cottage: outdoors next to the building (0.2 m off the wall)", VolumeMode.Bsp, out var next);
        Assert.False(next.Contains(plan.RoomId(0)));
    }
}
