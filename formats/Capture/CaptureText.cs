using System.Globalization;
using AcPhys.Core;

namespace AcPhys.Formats.Capture;

/// <summary>
/// The fields of a capture line, parsed from bytes without a string: decimal numbers as printed (their decimals counted),
/// cell ids (<c>0x</c> and 8 hex digits) and comma-separated cell lists.
/// </summary>
internal static class CaptureText
{
    /// <summary>The most cells a candidate list may hold (an outdoor list holds at most 9 per sphere).</summary>
    public const int MaxCandidates = 1024;

    /// <summary>What a coordinate must look like, for messages.</summary>
    public const string NumberExpected = "a finite decimal number such as -12.345 (no exponent, NaN or Infinity)";

    /// <summary>What a cell id must look like, for messages.</summary>
    public const string CellExpected = "a cell id, \"0x\" and 8 hex digits such as 0xA9B40031";

    /// <summary>
    /// Parses a decimal number as logs print them: an optional sign, digits, optionally a point and up to
    /// <see cref="PrintedPoint.MaxDecimals"/> digits. Exponents, NaN and infinities are refused: a capture's coordinate is
    /// a position a body held, and its printed digits are its precision.
    /// </summary>
    /// <param name="s">The field.</param>
    /// <param name="value">The value.</param>
    /// <param name="decimals">The digits printed after the point.</param>
    /// <returns>False when the field is not such a number.</returns>
    public static bool TryNumber(ReadOnlySpan<byte> s, out double value, out byte decimals)
    {
        value = 0;
        decimals = 0;
        int i = s.Length > 0 && (s[0] == (byte)'-' || s[0] == (byte)'+') ? 1 : 0;
        int intDigits = 0;
        while (i < s.Length && IsDigit(s[i]))
        {
            i++;
            intDigits++;
        }

        int fracDigits = 0;
        if (i < s.Length && s[i] == (byte)'.')
        {
            i++;
            while (i < s.Length && IsDigit(s[i]))
            {
                i++;
                fracDigits++;
            }
        }

        if (i != s.Length || intDigits == 0 || intDigits > 9 || (fracDigits == 0 && s[^1] == (byte)'.') || fracDigits > PrintedPoint.MaxDecimals)
        {
            return false;
        }

        decimals = (byte)fracDigits;
        return double.TryParse(s, NumberStyles.AllowLeadingSign | NumberStyles.AllowDecimalPoint, CultureInfo.InvariantCulture, out value);
    }

    /// <summary>Parses <c>0x</c> and exactly 8 hex digits.</summary>
    /// <param name="s">The field.</param>
    /// <param name="id">The id.</param>
    /// <returns>False when the field is not a cell id.</returns>
    public static bool TryCell(ReadOnlySpan<byte> s, out CellId id)
    {
        id = CellId.None;
        if (s.Length != 10 || s[0] != (byte)'0' || (s[1] | 0x20) != (byte)'x')
        {
            return false;
        }

        uint v = 0;
        for (int i = 2; i < 10; i++)
        {
            int h = Hex(s[i]);
            if (h < 0)
            {
                return false;
            }

            v = (v << 4) | (uint)h;
        }

        id = new CellId(v);
        return true;
    }

    /// <summary>Parses a comma-separated list of cell ids (an empty field is an empty list).</summary>
    /// <param name="s">The field.</param>
    /// <param name="into">Where the ids go (at least <see cref="MaxCandidates"/> long).</param>
    /// <param name="count">How many were read.</param>
    /// <returns>Null on success, or what is wrong.</returns>
    public static string? TryCells(ReadOnlySpan<byte> s, Span<CellId> into, out int count)
    {
        count = 0;
        if (s.IsEmpty)
        {
            return null;
        }

        while (true)
        {
            int comma = s.IndexOf((byte)',');
            var item = comma < 0 ? s : s[..comma];
            if (count == MaxCandidates)
            {
                return $"more than {MaxCandidates} candidate cells";
            }

            if (!TryCell(item, out into[count]))
            {
                return $"candidate {count + 1}: expected {CellExpected}, got \"{Quote(item)}\"";
            }

            count++;
            if (comma < 0)
            {
                return null;
            }

            s = s[(comma + 1)..];
        }
    }

    /// <summary>Splits a line into fields at a separator, as ranges.</summary>
    /// <param name="s">The line.</param>
    /// <param name="into">Where the ranges go.</param>
    /// <param name="separator">The separator byte.</param>
    /// <returns>The number of fields; more than <paramref name="into"/> holds is returned as its length + 1.</returns>
    public static int Split(ReadOnlySpan<byte> s, Span<Range> into, byte separator)
    {
        int n = 0, from = 0;
        while (true)
        {
            int at = s[from..].IndexOf(separator);
            if (n == into.Length)
            {
                return into.Length + 1;
            }

            into[n++] = at < 0 ? new Range(from, s.Length) : new Range(from, from + at);
            if (at < 0)
            {
                return n;
            }

            from += at + 1;
        }
    }

    /// <summary>Returns a field for a message: at most 40 characters, control characters escaped.</summary>
    /// <param name="s">The bytes (valid UTF-8: the line reader checked).</param>
    /// <returns>The text.</returns>
    public static string Quote(ReadOnlySpan<byte> s) =>
        AcPhys.Formats.Values.InputQuote.Line(System.Text.Encoding.UTF8.GetString(s[..Math.Min(s.Length, 160)]), 40);

    private static bool IsDigit(byte b) => (uint)(b - '0') <= 9;

    private static int Hex(byte b) =>
        (uint)(b - '0') <= 9 ? b - '0' : (uint)((b | 0x20) - 'a') <= 5 ? (b | 0x20) - 'a' + 10 : -1;
}
