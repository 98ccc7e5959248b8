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
}
