using System.Globalization;
using AcPhys.Core;
using AcPhys.Core.Text;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// Laws of the core value types that the mutation run showed untested: the id layout of facts §1.1, the land-cell
/// index of §1.2 and the lcoord grid of §1.3, as fixed-seed properties (mutation/survivors.md lists what each kills).
/// </summary>
public sealed class ValueTypeMutationTests
{
    [FixedSeedProperty(0x0DE5_0001, DisplayName = "facts §1.1: CellId's four ordering operators agree with the raw 32-bit value, ties included")]
    public Property CellId_OrderingOperatorsFollowRawValue() =>
        Prop.ForAll(FixedSeed.NearPairs.ToArbitrary(), p =>
        {
            var x = new CellId(p.A);
            var y = new CellId(p.B);
            return (x < y) == (p.A < p.B) && (x > y) == (p.A > p.B)
                && (x <= y) == (p.A <= p.B) && (x >= y) == (p.A >= p.B)
                && Math.Sign(x.CompareTo(y)) == Math.Sign(p.A.CompareTo(p.B));
        });

    [FixedSeedProperty(0x0DE5_0002, DisplayName = "facts §1.1: CellId equality is raw-value equality, through ==, !=, Equals(object) and the hash")]
    public Property CellId_EqualityIsRawValueEquality() =>
        Prop.ForAll(FixedSeed.NearPairs.ToArbitrary(), p =>
        {
            var x = new CellId(p.A);
            var y = new CellId(p.B);
            bool same = p.A == p.B;
            return (x == y) == same && (x != y) == !same && x.Equals(y) == same
                && x.Equals((object)y) == same && !x.Equals((object)p.A) && !x.Equals(null)
                && (!same || x.GetHashCode() == y.GetHashCode());
        });

    [FixedSeedProperty(0x0DE5_0003, DisplayName = "facts §1.1: a CellId's parts are bits 31..24, 23..16 and 15..0, and its landblock is the high word")]
    public Property CellId_PartsAreTheDocumentedBits() =>
        Prop.ForAll(FixedSeed.Uints.ToArbitrary(), v =>
        {
            var id = new CellId(v);
            return id.BlockX == (v >> 24) && id.BlockY == ((v >> 16) & 0xFF) && id.Low == (v & 0xFFFF)
                && id.Landblock.Value == (v >> 16) && id.Landblock.X == id.BlockX && id.Landblock.Y == id.BlockY
                && id.IsNone == (v == 0)
                && new CellId(id.BlockX, id.BlockY, id.Low).Value == v
                && id.WithLow(0x1234).Value == ((v & 0xFFFF0000) | 0x1234);
        });

    [FixedSeedProperty(0x0DE5_0004, DisplayName = "facts §1.1: the low-word classes are land 1..64, env 0x100..0xFFFD, block 0xFFFF; indoor is low >= 0x100 (block id and 0xFFFE included)")]
    public Property CellId_LowWordClassesMatchTheTable() =>
        Prop.ForAll(LowWords.ToArbitrary(), low =>
        {
            var id = new CellId(0xA9, 0xB4, low);
            bool land = low >= 1 && low <= 64;
            bool env = low >= 0x100 && low <= 0xFFFD;
            bool block = low == 0xFFFF;
            return id.IsLand == land && id.IsEnv == env && id.IsBlock == block
                && id.IsIndoorByLowWord == (low >= 0x100)
                && LandDefs.CellInRange(low) == (land || env || block);
        });

    [FixedSeedProperty(0x0DE5_0005, DisplayName = "facts §1.1: LandblockId(x, y) is the high word 0xXXYY, and equals the landblock of any id with those bytes")]
    public Property LandblockId_BytesComposeTheHighWord() =>
        Prop.ForAll(FixedSeed.Zip(FixedSeed.Bytes, FixedSeed.Bytes, LowWords).ToArbitrary(), t =>
        {
            var (x, y, low) = t;
            var block = new LandblockId(x, y);
            return block.X == x && block.Y == y && block.Value == ((x << 8) | y)
                && block == new CellId(x, y, low).Landblock
                && block == new LandblockId((ushort)((x << 8) | y))
                && block.BlockCell == new CellId(x, y, LandDefs.BlockCellId);
        });

    [FixedSeedProperty(0x0DE5_0006, DisplayName = "facts §1.3: a landblock is on the map exactly when both bytes are 0x00..0xFE, as blockid_to_lcoord says")]
    public Property LandblockId_IsOnMapIffNoFfByte() =>
        Prop.ForAll(Gen.Zip(FixedSeed.Bytes, FixedSeed.Bytes).ToArbitrary(), t =>
        {
            var block = new LandblockId(t.Item1, t.Item2);
            bool expected = t.Item1 <= 0xFE && t.Item2 <= 0xFE;
            return block.IsOnMap == expected && LandDefs.BlockIdToLcoord(block.BlockCell, out _) == expected;
        });

    [FixedSeedProperty(0x0DE5_0007, DisplayName = "facts §1.2: LandblockId.LandCell(cx, cy) has low word 1 + 8·cx + cy and is lcoord_to_gid(8·bx + cx, 8·by + cy)")]
    public Property LandblockId_LandCellIsTheXMajorIndex() =>
        Prop.ForAll(FixedSeed.Zip(FixedSeed.Bytes, FixedSeed.Bytes, Gen.Zip(Gen.Choose(0, 7), Gen.Choose(0, 7))).ToArbitrary(), t =>
        {
            var (x, y, (cx, cy)) = t;
            var block = new LandblockId(x, y);
            var cell = block.LandCell(cx, cy);
            bool shape = cell.Landblock == block && cell.Low == 1 + (8 * cx) + cy && cell.IsLand;
            bool onMap = !block.IsOnMap || cell == LandDefs.LcoordToGid((8 * x) + cx, (8 * y) + cy);
            return shape && onMap;
        });

    [FixedSeedProperty(0x0DE5_0008, DisplayName = "facts §1.2: LandblockId.LandCell refuses cx or cy outside 0..7, naming the argument, its value and the range")]
    public Property LandblockId_LandCellRefusesOutOfRange() =>
        Prop.ForAll(FixedSeed.Zip(OutOfRangeIndex, Gen.Choose(0, 7), Gen.Elements(true, false)).ToArbitrary(), t =>
        {
            var (bad, good, badIsX) = t;
            var block = new LandblockId(0x12, 0x34);
            var e = Assert.Throws<ArgumentOutOfRangeException>(() => { _ = badIsX ? block.LandCell(bad, good) : block.LandCell(good, bad); });
            return e.ParamName == (badIsX ? "cx" : "cy") && Equals(e.ActualValue, bad) && e.Message.Contains("[0, 7]", StringComparison.Ordinal);
        });

    [FixedSeedProperty(0x0DE5_0009, DisplayName = "facts §1.1: LandblockId equality is value equality, through ==, !=, Equals(object) and the hash")]
    public Property LandblockId_EqualityIsValueEquality() =>
        Prop.ForAll(FixedSeed.NearPairs.ToArbitrary(), p =>
        {
            var x = new LandblockId((ushort)p.A);
            var y = new LandblockId((ushort)p.B);
            bool same = (ushort)p.A == (ushort)p.B;
            return (x == y) == same && (x != y) == !same && x.Equals(y) == same
                && x.Equals((object)y) == same && !x.Equals((object)(ushort)p.A) && !x.Equals(null)
                && (!same || x.GetHashCode() == y.GetHashCode());
        });

    [FixedSeedProperty(0x0DE5_000A, DisplayName = "facts §1.1: LandblockId text is 0x and four upper-case hex digits, the first six characters of its block id's text")]
    public Property LandblockId_TextIsTheHighWordOfTheCellIdText() =>
        Prop.ForAll(Gen.Zip(FixedSeed.Bytes, FixedSeed.Bytes).ToArbitrary(), t =>
        {
            var block = new LandblockId(t.Item1, t.Item2);
            string text = block.ToString();
            return text.Length == 6
                && text == CellIdText.Format(block.BlockCell)[..6]
                && text[2..] == text[2..].ToUpperInvariant()
                && ushort.Parse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture) == block.Value;
        });

    [FixedSeedProperty(0x0DE5_000B, DisplayName = "facts §1.1: CellId text is 0x and eight upper-case hex digits of the raw value")]
    public Property CellId_TextIsUpperCaseHexOfTheRawValue() =>
        Prop.ForAll(FixedSeed.Uints.ToArbitrary(), v =>
        {
            var id = new CellId(v);
            string text = id.ToString();
            return text == CellIdText.Format(id) && text.Length == 10 && text.StartsWith("0x", StringComparison.Ordinal)
                && text[2..] == text[2..].ToUpperInvariant()
                && uint.Parse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture) == v;
        });

    [FixedSeedProperty(0x0DE5_000C, DisplayName = "facts §1.3: an lcoord's block origin is its landblock's south-west cell (8·⌊g/8⌋), off the map too")]
    public Property Lcoord_BlockOriginIsTheFlooredMultipleOfEight() =>
        Prop.ForAll(Gen.Zip(Ints, Ints).ToArbitrary(), t =>
        {
            var lc = new Lcoord(t.Item1, t.Item2);
            var origin = lc.BlockOrigin;
            bool floored = origin.X == 8 * Math.Floor(lc.X / 8.0) && origin.Y == 8 * Math.Floor(lc.Y / 8.0);
            bool blockOfGid = !lc.IsOnMap || (LandDefs.BlockIdToLcoord(LandDefs.LcoordToGid(lc), out var b) && b == origin);
            return floored && blockOfGid;
        });

    [FixedSeedProperty(0x0DE5_000D, DisplayName = "facts §1.3: Lcoord.Offset(dx, dy) moves dx cells east and dy cells north, unchecked")]
    public Property Lcoord_OffsetAddsTheSteps() =>
        Prop.ForAll(FixedSeed.Zip(Gen.Choose(-3000, 3000), Gen.Choose(-3000, 3000), Gen.Zip(Gen.Choose(-9, 9), Gen.Choose(-9, 9))).ToArbitrary(), t =>
        {
            var (x, y, (dx, dy)) = t;
            var moved = new Lcoord(x, y).Offset(dx, dy);
            return moved.X == x + dx && moved.Y == y + dy && moved.IsOnMap == LandDefs.InBounds(x + dx, y + dy);
        });

    /// <summary>Low words of every class and every class edge (facts §1.1), else any.</summary>
    private static Gen<ushort> LowWords { get; } = Gen.Frequency(
        (2, Gen.Elements<ushort>(0, 1, 2, 63, 64, 65, 0x80, 0xFF, 0x100, 0x101, 0xFFFC, 0xFFFD, 0xFFFE, 0xFFFF)),
        (1, Gen.Choose(0, 0xFFFF).Select(i => (ushort)i)));

    /// <summary>In-block indices just outside 0..7, and the int extremes.</summary>
    private static Gen<int> OutOfRangeIndex { get; } = Gen.Elements(-1, 8, 9, -8, int.MinValue, int.MaxValue);

    /// <summary>Lcoords around the map and block edges, negatives included.</summary>
    private static Gen<int> Ints { get; } = Gen.Frequency(
        (2, Gen.Choose(-20, 20)),
        (2, Gen.Choose(2020, 2060)),
        (1, Gen.Choose(-100_000, 100_000)));
}
