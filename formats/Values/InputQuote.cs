using System.Text.Json;

namespace AcPhys.Formats.Values;

/// <summary>
/// Quotes user input in an error message: at most <see cref="MaxChars"/> characters of it, so a 50 MB value never comes
/// back in a 50 MB error line (issue 19).
/// </summary>
public static class InputQuote
{
    /// <summary>The most characters of user input an error message quotes.</summary>
    public const int MaxChars = 80;

    /// <summary>Cuts a text to at most <paramref name="max"/> characters, marking the cut with its full length.</summary>
    /// <param name="text">The text.</param>
    /// <param name="max">The most characters to keep.</param>
    /// <returns>The text, or its start and "… (N characters)".</returns>
    public static string Brief(string text, int max = MaxChars) =>
        text.Length <= max ? text : string.Concat(text.AsSpan(0, max), string.Create(System.Globalization.CultureInfo.InvariantCulture, $"… ({text.Length:N0} characters)"));

    /// <summary>
    /// Escapes a text that came from outside (an implementation's name, error text or stderr line, a quoted answer) the
    /// way JSON escapes a string: control characters (newline, ESC, NUL, DEL, C1), the Unicode line and paragraph
    /// separators and lone surrogates become <c>\n</c>, <c>\u001b</c>, …, so the text cannot forge a line, drive a
    /// terminal or break an XML report (issue 28).
    /// </summary>
    /// <param name="text">The text.</param>
    /// <param name="keepLines">Keep <c>\n</c> and <c>\t</c> as they are (a multi-line block of the tool's own making).</param>
    /// <returns>The escaped text (the same instance when nothing needed escaping).</returns>
    public static string Escape(string text, bool keepLines = false)
    {
        int first = 0;
        while (first < text.Length && !NeedsEscape(text, first, keepLines))
        {
            first++;
        }

        if (first == text.Length)
        {
            return text;
        }

        var b = new System.Text.StringBuilder(text.Length + 16).Append(text, 0, first);
        for (int i = first; i < text.Length; i++)
        {
            char c = text[i];
            if (!NeedsEscape(text, i, keepLines))
            {
                b.Append(c);
                if (char.IsHighSurrogate(c))
                {
                    b.Append(text[++i]); // a valid pair: NeedsEscape checked the low half
                }

                continue;
            }

            b.Append(c switch
            {
                '\n' => "\\n",
                '\r' => "\\r",
                '\t' => "\\t",
                _ => string.Create(System.Globalization.CultureInfo.InvariantCulture, $"\\u{(int)c:x4}"),
            });
        }

        return b.ToString();
    }

    /// <summary>Escapes a text from outside (<see cref="Escape"/>) and cuts it to one console line of at most <paramref name="max"/> characters.</summary>
    /// <param name="text">The text.</param>
    /// <param name="max">The most characters to keep.</param>
    /// <returns>One safe line.</returns>
    public static string Line(string text, int max = MaxChars) => Brief(Escape(text), max);

    /// <summary>Quotes a JSON value briefly: its raw text, cut to <see cref="MaxChars"/> characters.</summary>
    /// <param name="e">The value.</param>
    /// <returns>The quote.</returns>
    public static string Json(JsonElement e)
    {
        if (e.ValueKind == JsonValueKind.String)
        {
            return TryText(e) is { } s ? "\"" + Line(s) + "\"" : "a string that is not valid text";
        }

        try
        {
            return Line(e.GetRawText());
        }
        catch (InvalidOperationException)
        {
            return "a value holding invalid text"; // a string inside it is invalid UTF-8 (found by the walk-json fuzz target)
        }
    }

    /// <summary>Returns a JSON string's text, or null when it is not valid text (a lone surrogate escape) or not a string.</summary>
    /// <param name="e">The value.</param>
    /// <returns>The text or null.</returns>
    public static string? TryText(JsonElement e)
    {
        if (e.ValueKind != JsonValueKind.String)
        {
            return null;
        }

        try
        {
            return e.GetString();
        }
        catch (InvalidOperationException)
        {
            return null;
        }
    }

    private static bool NeedsEscape(string text, int i, bool keepLines)
    {
        char c = text[i];
        if (keepLines && c is '\n' or '\t')
        {
            return false;
        }

        if (char.IsHighSurrogate(c))
        {
            return i + 1 >= text.Length || !char.IsLowSurrogate(text[i + 1]);
        }

        return char.IsControl(c) || char.IsLowSurrogate(c) || c is '\u2028' or '\u2029';
    }
}
