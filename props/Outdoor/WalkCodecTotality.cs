using AcPhys.Props.Support;
using AcPhys.Spec.Cases;

namespace AcPhys.Props.Outdoor;

/// <summary>The walk fuzz codec: every byte string becomes a bounded walk that starts in its block.</summary>
public sealed class WalkCodecTotality
{
    [CiProperty(MaxTest = 3000, DisplayName = "WalkCodec: any bytes decode to a walk of 1-3 spheres, at most 16 steps, starting inside its block")]
    public bool AnyBytesDecode(byte[] bytes)
    {
        var walk = WalkCodec.Decode(bytes ?? []);
        return walk.Body.Count is >= 1 and <= 3 && walk.Steps.Count <= WalkCodec.MaxSteps && walk.StartsInBlock
            && walk.StartCell.IsLand && walk.Steps.All(s => float.IsFinite(s.X) && float.IsFinite(s.Y));
    }

    [Fact(DisplayName = "WalkCodec: the empty input is the zero walk (cell 0x00000001 at the origin, no steps)")]
    public void EmptyInput()
    {
        var walk = WalkCodec.Decode([]);
        Assert.Equal(new AcPhys.Core.CellId(0x00000001), walk.StartCell);
        Assert.Empty(walk.Steps);
    }
}
