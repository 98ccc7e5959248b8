using System.Globalization;

namespace AcPhys.Cli.Tradeoffs;

/// <summary>Prints markdown tables on stdout (the docs paste them verbatim).</summary>
internal static class Markdown
{
    /// <summary>Prints a table.</summary>
    /// <param name="header">Column names.</param>
    /// <param name="rows">Rows, one cell per column.</param>
    public static void Table(IReadOnlyList<string> header, IEnumerable<IReadOnlyList<string>> rows)
    {
        Terminal.Line("| " + string.Join(" | ", header) + " |");
        Terminal.Line("|" + string.Concat(header.Select(_ => " --- |")));
        foreach (var row in rows)
        {
            Terminal.Line("| " + string.Join(" | ", row) + " |");
        }

        Terminal.Line();
    }

    /// <summary>Formats an integer with thousands separators.</summary>
    /// <param name="v">The value.</param>
    /// <returns>The text.</returns>
    public static string N(long v) => v.ToString("N0", CultureInfo.InvariantCulture);

    /// <summary>Formats a rate as a percentage.</summary>
    /// <param name="part">The part.</param>
    /// <param name="whole">The whole.</param>
    /// <returns>The text, "—" when the whole is 0.</returns>
    public static string Pct(long part, long whole)
    {
        if (whole == 0)
        {
            return "—";
        }

        double pct = 100.0 * part / whole;
        return pct.ToString(part == 0 ? "0" : pct < 0.001 ? "0.##E+0" : "0.###", CultureInfo.InvariantCulture) + " %";
    }

    /// <summary>Formats a double in round-trip form.</summary>
    /// <param name="v">The value.</param>
    /// <returns>The text.</returns>
    public static string R(double v) => v.ToString("G6", CultureInfo.InvariantCulture);

    /// <summary>Formats a float32 in round-trip form.</summary>
    /// <param name="v">The value.</param>
    /// <returns>The text.</returns>
    public static string F(float v) => v.ToString("R", CultureInfo.InvariantCulture);
}
