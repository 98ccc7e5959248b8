using System.Globalization;

namespace AcPhys.Cli;

/// <summary>Culture-invariant formatting of counts, shares and durations for reports.</summary>
internal static class Fmt
{
    /// <summary>Formats a count with thousands separators, e.g. <c>4,161,600</c>.</summary>
    /// <param name="n">The count.</param>
    /// <returns>The text.</returns>
    public static string Count(long n) => n.ToString("N0", CultureInfo.InvariantCulture);

    /// <summary>Formats a share as a percentage with one decimal, e.g. <c>97.3%</c>.</summary>
    /// <param name="part">The part.</param>
    /// <param name="whole">The whole.</param>
    /// <returns>The text, or <c>-</c> when the whole is zero.</returns>
    public static string Percent(long part, long whole) =>
        whole == 0 ? "-" : (100.0 * part / whole).ToString("0.0", CultureInfo.InvariantCulture) + "%";

    /// <summary>Formats a duration, e.g. <c>0.42 s</c> or <c>12.3 s</c>.</summary>
    /// <param name="elapsed">The duration.</param>
    /// <returns>The text.</returns>
    public static string Seconds(TimeSpan elapsed) =>
        elapsed.TotalSeconds.ToString(elapsed.TotalSeconds < 10 ? "0.00" : "0.0", CultureInfo.InvariantCulture) + " s";

    /// <summary>Formats a 64-bit value in decimal.</summary>
    /// <param name="value">The value.</param>
    /// <returns>The text.</returns>
    public static string Decimal(ulong value) => value.ToString(CultureInfo.InvariantCulture);
}
