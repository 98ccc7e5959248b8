using System.Globalization;
using AcPhys.Core;
using AcPhys.Core.Text;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The cell id text format <c>0xAABBCCCC</c> (the notation of facts §1.1 and §8): exactly the prefix 0x or 0X and eight
/// hex digits of either case parse, to the same id; a wrong first or second character is refused on its own.
/// </summary>
public sealed class CellIdTextMutationTests
{
    [FixedSeedProperty(0x7E47_0001, DisplayName = "facts §1.1 notation: 0x or 0X plus eight hex digits of either case parse to the raw value; any other two-character prefix is refused")]
    public Property CellIdText_OnlyTheHexPrefixParses() =>
        Prop.ForAll(FixedSeed.Zip(FixedSeed.Uints, Prefixes, Gen.Elements(true, false)).ToArbitrary(), t =>
        {
            var (v, prefix, lower) = t;
            string digits = v.ToString("X8", CultureInfo.InvariantCulture);
            string text = prefix + (lower ? digits.ToLowerInvariant() : digits);
            bool accepted = prefix is "0x" or "0X";
            bool ok = CellIdText.TryParse(text, out var id);
            return ok == accepted && id == (accepted ? new CellId(v) : CellId.None);
        });

    [FixedSeedProperty(0x7E47_0002, DisplayName = "facts §1.1 notation: Format writes 0x then eight upper-case hex digits, and TryParse reads it back")]
    public Property CellIdText_FormatIsPrefixAndEightUpperHexDigits() =>
        Prop.ForAll(FixedSeed.Uints.ToArbitrary(), v =>
        {
            string text = CellIdText.Format(new CellId(v));
            return text == "0x" + v.ToString("X8", CultureInfo.InvariantCulture)
                && CellIdText.TryParse(text, out var back) && back.Value == v;
        });

    [Theory(DisplayName = "facts §1.1 notation: a ten-character text with a bad first or second character is refused")]
    [InlineData("1xA9B40031")] // first character wrong, second right
    [InlineData("Ox00000001")] // letter O for zero
    [InlineData("0yA9B40031")] // second character wrong, first right
    [InlineData("00A9B40031")] // no x at all
    [InlineData("x0A9B40031")] // swapped prefix
    public void CellIdText_RefusesABadPrefixCharacter(string text)
    {
        Assert.False(CellIdText.TryParse(text, out var id));
        Assert.Equal(CellId.None, id);
    }

    /// <summary>Two-character prefixes: the two accepted ones often, and near misses in each position.</summary>
    private static Gen<string> Prefixes { get; } = Gen.Frequency(
        (3, Gen.Elements("0x", "0X")),
        (2, Gen.Elements("1x", "1X", "Ox", "0y", "0Y", "00", "x0", "X0", "0 ", " x", "xx")));
}
