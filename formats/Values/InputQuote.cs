using System.Text.Json;

namespace AcPhys.Spec.Values;

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

    /// <summary>Quotes a JSON value briefly: its raw text, cut to <see cref="MaxChars"/> characters.</summary>
    /// <param name="e">The value.</param>
    /// <returns>The quote.</returns>
    public static string Json(JsonElement e)
    {
        if (e.ValueKind == JsonValueKind.String)
        {
            return TryText(e) is { } s ? "\"" + Brief(s) + "\"" : "a string that is not valid text";
        }

        try
        {
            return Brief(e.GetRawText());
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
}
