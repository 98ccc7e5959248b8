using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Props.Core;

/// <summary>Unit facts of the LandDefs functions (facts §1–§2, §7 #15–16): each row says why it is there.</summary>
public sealed class LandDefsFacts
{
    [Theory(DisplayName = "cell_in_range: land 1..64, env 0x100..0xFFFD, block 0xFFFF; nothing else")]
    [InlineData(0x0000, false)] // zero low word
    [InlineData(0x0001, true)]  // first land cell
    [InlineData(0x0040, true)]  // last land cell
    [InlineData(0x0041, false)] // just past the land range
    [InlineData(0x00FF, false)] // gap below env
    [InlineData(0x0100, true)]  // first env cell
    [InlineData(0xFFFD, true)]  // last env cell
    [InlineData(0xFFFE, false)] // reserved
    [InlineData(0xFFFF, true)]  // the block itself
    public void CellInRange(int low, bool expected) => Assert.Equal(expected, LandDefs.CellInRange((ushort)low));

    [Fact(DisplayName = "blockid_to_lcoord: retail fails for id 0 (facts §7 #16) and for a 0xFF byte; ignores the low word")]
    public void BlockIdToLcoord()
    {
        Assert.False(LandDefs.BlockIdToLcoord(CellId.None, out _));
        Assert.True(LandDefs.BlockIdToLcoord(new CellId(0x00000001), out var origin));
        Assert.Equal(new Lcoord(0, 0), origin);
        Assert.True(LandDefs.BlockIdToLcoord(new CellId(0xA9B4FFFE), out var lc));
        Assert.Equal(new Lcoord(0xA9 * 8, 0xB4 * 8), lc);
        Assert.False(LandDefs.BlockIdToLcoord(new CellId(0xFF000001), out _));
        Assert.False(LandDefs.BlockIdToLcoord(new CellId(0x00FF0001), out _));
    }

    [Fact(DisplayName = "inbound_valid_cellid: retail tests block X and Y (facts §7 #15)")]
    public void InboundValidCellId()
    {
        Assert.True(LandDefs.InboundValidCellId(new CellId(0xFEFE0040)));
        Assert.False(LandDefs.InboundValidCellId(new CellId(0x00FF0001)));
        Assert.False(LandDefs.InboundValidCellId(new CellId(0xFF000001)));
        Assert.False(LandDefs.InboundValidCellId(new CellId(0x12340041)));
    }

    [Fact(DisplayName = "gid_to_lcoord: x is the major index; env and block low words are rejected as retail")]
    public void GidToLcoord()
    {
        Assert.True(LandDefs.GidToLcoord(new CellId(0xA9B40031), out var lc)); // idx 48 → cx 6, cy 0
        Assert.Equal(new Lcoord((0xA9 * 8) + 6, 0xB4 * 8), lc);
        Assert.False(LandDefs.GidToLcoord(new CellId(0xA9B40100), out _));
        Assert.False(LandDefs.GidToLcoord(new CellId(0xA9B4FFFF), out _));
    }

    [Fact(DisplayName = "lcoord_to_gid: 0 off the map, exact ids at the corners")]
    public void LcoordToGid()
    {
        Assert.Equal(new CellId(0x00000001), LandDefs.LcoordToGid(0, 0));
        Assert.Equal(new CellId(0xFEFE0040), LandDefs.LcoordToGid(2039, 2039));
        Assert.Equal(CellId.None, LandDefs.LcoordToGid(-1, 0));
        Assert.Equal(CellId.None, LandDefs.LcoordToGid(0, 2040));
        Assert.Equal(CellId.None, LandDefs.LcoordToGid(int.MinValue, int.MaxValue));
    }

    [Theory(DisplayName = "get_outside_lcoord: floor toward -inf; 24.0 and 192.0 belong to the next cell/block")]
    [InlineData(-0.5f, 7, -1)]       // previous cell, previous block
    [InlineData(0f, 8, 0)]
    [InlineData(23.999998f, 8, 0)]   // one ULP below the line
    [InlineData(24f, 9, 1)]          // exactly on the line
    [InlineData(192f, 16, 8)]        // next block
    public void GetOutsideLcoord(float x, int expectedGx, int expectedCxOffset)
    {
        Assert.True(LandDefs.GetOutsideLcoord(new CellId(0x01010001), x, 5f, out var lc));
        Assert.Equal(expectedGx, lc.X);
        Assert.Equal(8 + expectedCxOffset, lc.X);
        Assert.Equal(8, lc.Y);
    }

    [Theory(DisplayName = "get_outside_lcoord: non-finite and huge inputs fail, never lcoord 0")]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    [InlineData(float.NegativeInfinity)]
    [InlineData(float.MaxValue)]
    [InlineData(float.MinValue)]
    [InlineData(1e30f)]
    public void GetOutsideLcoord_Rejects(float x)
    {
        Assert.False(LandDefs.GetOutsideLcoord(new CellId(0x00000001), x, 0f, out var lc));
        Assert.Equal(default, lc);
        var id = new CellId(0x00000001);
        float rx = x, ry = 0f;
        Assert.False(LandDefs.AdjustToOutside(ref id, ref rx, ref ry));
        Assert.Equal(CellId.None, id);
    }

    [Fact(DisplayName = "GetBlockOffset: zero within a block, 192 m per block step, antisymmetric, no validation (id 0 is block 0,0)")]
    public void GetBlockOffset()
    {
        Assert.Equal(Vector3.Zero, LandDefs.GetBlockOffset(new CellId(0xA9B40001), new CellId(0xA9B40100)));
        Assert.Equal(new Vector3(0, -192, 0), LandDefs.GetBlockOffset(new CellId(0xA9B40031), new CellId(0xA9B30038)));
        Assert.Equal(new Vector3(192, 192, 0), LandDefs.GetBlockOffset(new CellId(0x00000001), new CellId(0x01010001)));
        Assert.Equal(new Vector3(192 * 0xFF, 0, 0), LandDefs.GetBlockOffset(CellId.None, new CellId(0xFF000001)));
        Assert.Equal(-LandDefs.GetBlockOffset(new CellId(0x10200001), new CellId(0x3040FFFF)), LandDefs.GetBlockOffset(new CellId(0x3040FFFF), new CellId(0x10200001)));
    }

    [Theory(DisplayName = "InBlock: lower bound inclusive, upper strict")]
    [InlineData(1f, 1f, 1f, true)]      // x == r is in
    [InlineData(0.99f, 5f, 1f, false)]  // x < r is out
    [InlineData(190.99f, 5f, 1f, true)]
    [InlineData(191f, 5f, 1f, false)]   // x == 192 - r is out
    [InlineData(96f, 96f, 0f, true)]
    public void InBlock(float x, float y, float r, bool expected) => Assert.Equal(expected, LandDefs.InBlock(new Vector3(x, y, 0), r));
}
