using AcPhys.Core;
using AcPhys.Core.Text;
using AcPhys.Props.Support;
using AcPhys.Spec.Running;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Core;

/// <summary>Equality, ordering and text laws of the core value types, as FsCheck properties with fixed seeds.</summary>
public sealed class ValueTypeLaws
{
    [CiProperty(MaxTest = 2000, DisplayName = "CellId: text round-trips through 0xAABBCCCC for every 32-bit pattern")]
    public Property CellId_RoundTripsThroughText() =>
        Prop.ForAll(ArbMap.Default.ArbFor<uint>(), v =>
        {
            var id = new CellId(v);
            string text = CellIdText.Format(id);
            return text.Length == 10 && CellIdText.TryParse(text, out var back) && back == id && CellIdText.TryParse(text.ToLowerInvariant(), out var lower) && lower == id;
        });

    [CiProperty(MaxTest = 2000, DisplayName = "CellId: parts recompose to the id; equality, hash and ordering agree with the raw value")]
    public Property CellId_PartsAndOrdering() =>
        Prop.ForAll(ArbMap.Default.ArbFor<uint>(), ArbMap.Default.ArbFor<uint>(), (a, b) =>
        {
            var x = new CellId(a);
            var y = new CellId(b);
            return new CellId(x.BlockX, x.BlockY, x.Low) == x
                && (x == y) == (a == b) && (x != y) == (a != b)
                && (x < y) == (a < b) && (x >= y) == (a >= b)
                && x.CompareTo(y) == a.CompareTo(b)
                && (x.Equals(y) == x.GetHashCode().Equals(y.GetHashCode()) || !x.Equals(y));
        });

    [Theory(DisplayName = "CellIdText: anything but 0x + 8 hex digits is refused without throwing")]
    [InlineData(null)]
    [InlineData("")]
    [InlineData("A9B40031")]      // no prefix
    [InlineData("0xA9B4003")]     // 7 digits
    [InlineData("0xA9B400311")]   // 9 digits
    [InlineData("0xA9B4003G")]    // not hex
    [InlineData("0x-9B40031")]    // sign
    [InlineData(" 0xA9B40031")]   // whitespace
    public void CellIdText_RefusesMalformed(string? text)
    {
        Assert.False(CellIdText.TryParse(text, out var id));
        Assert.Equal(CellId.None, id);
    }

    [Fact(DisplayName = "Seed: text round-trips; gamma must be odd")]
    public void Seed_RoundTrips()
    {
        var s = new Seed(123456789012345UL, 0x9E3779B97F4A7C15UL, 17);
        Assert.True(Seed.TryParse(s.ToString(), out var back));
        Assert.Equal(s, back);
        Assert.False(Seed.TryParse("1,2", out _));
        Assert.False(Seed.TryParse("x,y", out _));
        Assert.True(Seed.TryParse("0x10,0x3", out var hex));
        Assert.Equal(new Seed(16, 3), hex);
    }
}
