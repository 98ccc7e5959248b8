using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Faults;

namespace AcPhys.Props.Indoor;

/// <summary>
/// Issue 51, SCENE-WALK-MEMO: the reference's trace of a scene walk is run once and shared by every judge of that walk;
/// a planted fault, a port, or the reference declaring ace-keeps-stale-cells is asked again every time.
/// </summary>
public sealed class SceneWalkMemoTests
{
    // The scene target's "one-room-in-and-back" seed: a cottage room entered and left.
    private static readonly byte[] OneRoom = [0x00, 0x00, 0x08, 0x08, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x30, 0x30, 0x40, 0x40, 0x01, 0x00, 0x04, 0x04, 0x00];

    [Theory(DisplayName = "SCENE-WALK-MEMO: the reference's trace of one walk is run once, and is what a fresh reference answers")]
    [InlineData(false)]
    [InlineData(true)]
    public void ReferenceTraceIsShared(bool loadCells)
    {
        var walk = SceneCodec.DecodeWalk(OneRoom);
        var first = SceneWalkRunner.Run(ReferenceAdapter.Instance, walk, loadCells);
        Assert.Same(first, SceneWalkRunner.Run(ReferenceAdapter.Instance, walk, loadCells));

        var fresh = SceneWalkRunner.Run(new ReferenceAdapter(), walk, loadCells); // another instance: its own run
        Assert.NotSame(first, fresh);
        Assert.True(first.Count > 1);
        Assert.Equal(first.Select(s => (s.Containing, string.Join(",", s.Cells))), fresh.Select(s => (s.Containing, string.Join(",", s.Cells))));
    }

    [Fact(DisplayName = "SCENE-WALK-MEMO: a planted fault and a reference keeping stale cells are asked again for every run")]
    public void OthersAreAskedEveryTime()
    {
        var walk = SceneCodec.DecodeWalk(OneRoom);
        var fault = PlantedFaults.Create("stale-scene-array");
        Assert.NotSame(SceneWalkRunner.Run(fault, walk, false), SceneWalkRunner.Run(fault, walk, false));

        var stale = new ReferenceAdapter { Indoor = new IndoorFidelity(AceKeepsStaleCells: true) };
        Assert.NotSame(SceneWalkRunner.Run(stale, walk, false), SceneWalkRunner.Run(stale, walk, false));
    }
}
