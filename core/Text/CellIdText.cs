using System.Globalization;

namespace AcPhys.Core.Text;

/// <summary>Parses and formats cell ids as <c>0xAABBCCCC</c>. Parsing never throws.</summary>
public static class CellIdText
{
    /// <summary>Formats an id as <c>0x</c> followed by eight upper-case hex digits.</summary>
    /// <param name="id">The id.</param>
    /// <returns>The text, e.g. <c>0xA9B40031</c>.</returns>
    public static string Format(CellId id) => "0x" + id.Value.ToString("X8", CultureInfo.InvariantCulture);

    /// <summary>Parses <c>0x</c> followed by exactly eight hex digits (either case).</summary>
    /// <param name="text">The text to parse.</param>
    /// <param name="id">The parsed id, or <see cref="CellId.None"/> on failure.</param>
    /// <returns>True on success; false for any other text, including null.</returns>
    public static bool TryParse(string? text, out CellId id)
    {
        id = CellId.None;
        if (text is null || text.Length != 10 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X'))
        {
            return false;
        }

        if (!uint.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out var value))
        {
            return false;
        }

        id = new CellId(value);
        return true;
    }
}
