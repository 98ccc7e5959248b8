using System.Globalization;

namespace AcPhys.Cli.Render;

/// <summary>Text helpers shared by the SVG renderers: numbers, escaping, clipping.</summary>
internal static class SvgText
{
    /// <summary>Formats a coordinate with at most three decimals, invariant culture.</summary>
    /// <param name="v">The value.</param>
    /// <returns>The text.</returns>
    public static string Num(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);

    /// <summary>Escapes text for element content and attribute values.</summary>
    /// <param name="s">The text.</param>
    /// <returns>The escaped text.</returns>
    public static string Escape(string s) => s.Replace("&", "&amp;", StringComparison.Ordinal).Replace("<", "&lt;", StringComparison.Ordinal)
        .Replace(">", "&gt;", StringComparison.Ordinal).Replace("\"", "&quot;", StringComparison.Ordinal);

    /// <summary>Shortens text to a number of characters, ending with an ellipsis when cut.</summary>
    /// <param name="s">The text.</param>
    /// <param name="max">Most characters.</param>
    /// <returns>The text.</returns>
    public static string Clip(string s, int max) => s.Length <= max ? s : s[..Math.Max(max - 1, 1)] + "…";

    /// <summary>Breaks text into lines of at most <paramref name="max"/> characters at spaces (a longer word is split), so header lines wrap instead of being cut.</summary>
    /// <param name="s">The text.</param>
    /// <param name="max">Most characters per line.</param>
    /// <returns>The lines, at least one.</returns>
    public static List<string> Wrap(string s, int max)
    {
        max = Math.Max(max, 8);
        var lines = new List<string>();
        string rest = s;
        while (rest.Length > max)
        {
            int cut = rest.LastIndexOf(' ', max);
            if (cut <= 0)
            {
                cut = max;
            }

            lines.Add(rest[..cut].TrimEnd());
            rest = rest[cut..].TrimStart();
        }

        lines.Add(rest);
        return lines;
    }
}
