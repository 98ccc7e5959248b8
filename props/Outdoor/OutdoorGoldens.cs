using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Props.Outdoor;

/// <summary>The add_all_outside_cells vectors of facts §8 (one sphere, position 0xA9B40005), insertion order pinned.</summary>
public sealed class OutdoorGoldens
{
    public static TheoryData<float, float, float, uint[]> Vectors => new()
    {
        { 0.1f, 100f, 0.5f, [0xA9B40005, 0xA8B4003D] },                          // west edge: neighbour in the block to the west
        { 0.1f, 0.2f, 0.5f, [0xA9B40001, 0xA8B40039, 0xA8B30040, 0xA9B30008] },  // 4-block corner
        { 24.0f, 50f, 0.5f, [0xA9B4000B, 0xA9B40003] },                          // exactly on x = 24
        { 23.6f, 23.6f, 0.5f, [0xA9B40001, 0xA9B40009, 0xA9B4000A, 0xA9B40002] },// interior corner
        { 24.5f, 12f, 0.5f, [0xA9B40009] },                                      // pt.x == r: strict, nothing added
        { 12f, 12f, 0.5f, [0xA9B40001] },                                        // cell centre
    };

    [Theory(DisplayName = "facts §8: add_all_outside_cells, one sphere, insertion order")]
    [MemberData(nameof(Vectors))]
    public void AddAllOutsideCells_MatchesVector(float x, float y, float r, uint[] expected)
    {
        var array = new CellArray();
        OutdoorCells.AddAllOutsideCells(array, new CellId(0xA9B40005), Vector3.Zero, [new Sphere(new Vector3(x, y, 0), r)], OpenLand.Instance);
        Assert.Equal(expected.Select(v => new CellId(v)), array.ToIdArray());
    }

    [Fact(DisplayName = "facts §4 tie: on x = 24 the retail pick is the last hit (cx 0) while AdjustToOutside says cx 1")]
    public void PickOnLineIsLastHit()
    {
        var array = new CellArray();
        var center = new Vector3(24f, 50f, 0);
        OutdoorCells.AddAllOutsideCells(array, new CellId(0xA9B40005), Vector3.Zero, [new Sphere(center, 0.5f)], OpenLand.Instance);
        Assert.Equal(new CellId(0xA9B40003), ContainingCell.PickOutdoor(array, new CellId(0xA9B40005), center, PickPolicy.Retail, CellId.None));
        Assert.Equal(new CellId(0xA9B4000B), ContainingCell.PickOutdoor(array, new CellId(0xA9B40005), center, PickPolicy.CurrentFirst, new CellId(0xA9B4000B)));
    }

    [Fact(DisplayName = "facts §3.5: the AddedOutside latch makes a second call a no-op until Reset")]
    public void LatchAndReset()
    {
        var array = new CellArray();
        Sphere[] spheres = [new Sphere(new Vector3(12, 12, 0), 0.5f)];
        OutdoorCells.AddAllOutsideCells(array, new CellId(0xA9B40005), Vector3.Zero, spheres, OpenLand.Instance);
        OutdoorCells.AddAllOutsideCells(array, new CellId(0x10100005), Vector3.Zero, spheres, OpenLand.Instance);
        Assert.Equal([new CellId(0xA9B40001)], array.ToIdArray());
        array.Reset();
        OutdoorCells.AddAllOutsideCells(array, new CellId(0x10100005), Vector3.Zero, spheres, OpenLand.Instance);
        Assert.Equal([new CellId(0x10100001)], array.ToIdArray());
    }

    [Fact(DisplayName = "facts §3.3 b: a sphere whose centre leaves the map ends the sphere loop; earlier cells stay")]
    public void FailedSphereBreaksLoop()
    {
        var array = new CellArray();
        Sphere[] spheres = [new Sphere(new Vector3(12, 12, 0), 0.5f), new Sphere(new Vector3(-30, 12, 0), 0.5f), new Sphere(new Vector3(36, 12, 0), 0.5f)];
        OutdoorCells.AddAllOutsideCells(array, new CellId(0x00000001), Vector3.Zero, spheres, OpenLand.Instance);
        Assert.Equal([new CellId(0x00000001)], array.ToIdArray());
    }
}

/// <summary>Unloaded landblocks (facts §3.1, §7 #2): retail adds their cells as load hints; ACE drops them.</summary>
public sealed class LoadHints
{
    private sealed class OnlyBlock(LandblockId loaded) : ILandscape
    {
        public bool IsLoaded(LandblockId block) => block == loaded;
    }

    private static readonly Sphere[] Corner = [new Sphere(new System.Numerics.Vector3(0.1f, 0.2f, 0), 0.5f)];

    [Fact(DisplayName = "facts §3.1: retail adds cells of unloaded blocks as load hints, in the same order, never picked")]
    public void RetailAddsLoadHints()
    {
        var array = new CellArray();
        var position = new CellId(0xA9B40005);
        var containing = CellQuery.FindCellListOutdoor(array, position, Corner, CellId.None, PickPolicy.Retail, new OnlyBlock(position.Landblock));
        Assert.Equal([0xA9B40001u, 0xA8B40039u, 0xA8B30040u, 0xA9B30008u], array.ToIdArray().Select(c => c.Value));
        Assert.Equal([true, false, false, false], Enumerable.Range(0, array.Count).Select(i => array[i].Loaded));
        Assert.Equal(new CellId(0xA9B40001), containing);
    }

    [Fact(DisplayName = "facts §7 #2: with ACE fidelity, cells of unloaded blocks are dropped")]
    public void AceDropsUnloaded()
    {
        var array = new CellArray();
        var position = new CellId(0xA9B40005);
        CellQuery.FindCellListOutdoor(array, position, Corner, CellId.None, PickPolicy.Retail, new OnlyBlock(position.Landblock), OutdoorFidelity.Ace);
        Assert.Equal([new CellId(0xA9B40001)], array.ToIdArray());
    }

    [Fact(DisplayName = "facts §4: a load hint is never picked, even when its square holds the centre")]
    public void HintIsNeverPicked()
    {
        var array = new CellArray();
        var position = new CellId(0xA9B40005);
        var westOfLine = new[] { new Sphere(new System.Numerics.Vector3(-0.5f, 100, 0), 0.5f) };
        var containing = CellQuery.FindCellListOutdoor(array, position, westOfLine, CellId.None, PickPolicy.Retail, new OnlyBlock(position.Landblock));
        Assert.Contains(new CellId(0xA8B4003D), array.ToIdArray());
        Assert.Equal(CellId.None, containing);
    }
}
