using AcPhys.Core;

namespace AcPhys.Props.Core;

/// <summary>The AdjustToOutside test vectors of facts §8, pinned (float32 inputs).</summary>
public sealed class AdjustToOutsideGoldens
{
    public static TheoryData<uint, float, float, bool, uint, float, float> Vectors => new()
    {
        { 0xA9B40031, 150f, -0.5f, true, 0xA9B30038, 150f, 191.5f },      // seed capture: south across the block line
        { 0xA9B40031, 150f, -100f, true, 0xA9B30034, 150f, 92f },         // seed golden
        { 0xA9B40001, 192f, 10f, true, 0xAAB40001, 0f, 10f },             // exactly 192 belongs to the next block
        { 0xA9B40001, -0.0001f, 10f, true, 0xA9B40001, 0f, 10f },         // inside the EPS band: snapped, stays
        { 0xA9B40001, -0.0003f, 10f, true, 0xA8B40039, 191.9997f, 10f },  // outside the band: previous block
        { 0xA9B40001, 24f, 24f, true, 0xA9B4000A, 24f, 24f },             // exactly 24 belongs to the next cell
        { 0xA9B40100, 30f, 30f, true, 0xA9B4000A, 30f, 30f },             // env id maps to the column under it
        { 0xA9B4FFFF, 100f, 50f, true, 0xA9B40023, 100f, 50f },           // block id likewise
        { 0x00000001, -1f, 5f, false, 0, -1f, 5f },                          // west of the map
        { 0xFE000001, 192f, 5f, false, 0, 192f, 5f },                     // gx would be 2040
        { 0xFF000001, 5f, 5f, false, 0, 5f, 5f },                         // block byte 0xFF
        { 0xA9B40000, 1f, 1f, false, 0, 1f, 1f },                         // low word 0 is invalid
    };

    [Theory(DisplayName = "facts §8: AdjustToOutside vectors")]
    [MemberData(nameof(Vectors))]
    public void AdjustToOutside_MatchesVector(uint id, float x, float y, bool ok, uint expectedId, float expectedX, float expectedY)
    {
        var cell = new CellId(id);
        float rx = x, ry = y;
        bool result = LandDefs.AdjustToOutside(ref cell, ref rx, ref ry);
        Assert.Equal(ok, result);
        Assert.Equal(new CellId(expectedId), cell);
        Assert.Equal(expectedX, rx, 0.00002f);
        Assert.Equal(expectedY, ry, 0.00002f);
    }

    [Fact(DisplayName = "facts §2.1: z is never touched and a failure on a bad low word leaves x, y untouched")]
    public void AdjustToOutside_Vector3KeepsZ()
    {
        var cell = new CellId(0xA9B40031);
        var p = new System.Numerics.Vector3(150f, -0.5f, 42.5f);
        Assert.True(LandDefs.AdjustToOutside(ref cell, ref p));
        Assert.Equal(42.5f, p.Z);

        var bad = new CellId(0xA9B40041);
        float bx = -0.0001f, by = 3f;
        Assert.False(LandDefs.AdjustToOutside(ref bad, ref bx, ref by));
        Assert.Equal(CellId.None, bad);
        Assert.Equal(-0.0001f, bx); // not snapped: the low-word test comes first (step 1)
    }

    [Fact(DisplayName = "facts §2.1: an off-map failure keeps the snapped point")]
    public void AdjustToOutside_OffMapKeepsSnappedPoint()
    {
        var cell = new CellId(0x00000001);
        float x = -24f, y = -0.0001f;
        Assert.False(LandDefs.AdjustToOutside(ref cell, ref x, ref y));
        Assert.Equal(0f, y);
        Assert.False(float.IsNegative(y));
    }
}
