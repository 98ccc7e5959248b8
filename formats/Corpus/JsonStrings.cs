using System.Numerics;
using System.Runtime.InteropServices;
using System.Text.Json;
using System.Text.Unicode;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// Finds the first string (value or property name) of a JSON document that cannot be read as .NET text.
/// <see cref="JsonDocument"/> accepts a lone surrogate escape such as <c>"\ud800"</c>, and only reading the string
/// (<see cref="JsonElement.GetString"/>, <see cref="JsonProperty.Name"/>, or a lookup by name that meets it) throws
/// InvalidOperationException, wherever that happens. Checking the whole document once, right after parsing, lets a
/// reader reject such input with its own format error (found by the serve-request fuzz target).
/// </summary>
internal static class JsonStrings
{
    /// <summary>Returns the JSON path of the first unreadable string under <paramref name="e"/>, or null when every string reads.</summary>
    /// <param name="e">The element.</param>
    /// <param name="at">Its JSON path.</param>
    /// <returns>The path, or null.</returns>
    public static string? FirstUnreadable(JsonElement e, string at)
    {
        // A string reads unless it holds a surrogate escape or invalid UTF-8: one scan of the element's raw text clears
        // almost every document without walking it (issue #26); a document that may hold one is walked for the path.
        if (e.ValueKind is JsonValueKind.String or JsonValueKind.Array or JsonValueKind.Object)
        {
            var raw = JsonMarshal.GetRawUtf8Value(e);
            if (!MayHoldSurrogateEscape(raw) && Utf8.IsValid(raw))
            {
                return null;
            }
        }

        return Walk(e, at);
    }

    /// <summary>
    /// Tells whether JSON text may hold an escaped UTF-16 surrogate (<c>\uD800</c> to <c>\uDFFF</c>), the only escape
    /// that can leave a string unreadable. False positives (an escaped backslash before <c>ud8</c>) only cost a closer look.
    /// </summary>
    /// <typeparam name="T">The code unit: <see cref="byte"/> for UTF-8, <see cref="char"/> for a .NET string.</typeparam>
    /// <param name="text">The text.</param>
    /// <returns>False when the text certainly holds no such escape.</returns>
    public static bool MayHoldSurrogateEscape<T>(ReadOnlySpan<T> text)
        where T : unmanaged, IBinaryInteger<T>
    {
        var backslash = T.CreateTruncating('\\');
        for (int at = text.IndexOf(backslash); at >= 0 && at + 3 < text.Length; at = NextBackslash(text, at + 1))
        {
            int u = int.CreateTruncating(text[at + 1]), d = int.CreateTruncating(text[at + 2]) | 0x20, h = int.CreateTruncating(text[at + 3]) | 0x20;
            if (u == 'u' && d == 'd' && (h is >= '8' and <= '9' or >= 'a' and <= 'f'))
            {
                return true;
            }
        }

        return false;
    }

    private static int NextBackslash<T>(ReadOnlySpan<T> text, int from)
        where T : unmanaged, IBinaryInteger<T>
    {
        int next = text[from..].IndexOf(T.CreateTruncating('\\'));
        return next < 0 ? -1 : from + next;
    }

    private static string? Walk(JsonElement e, string at)
    {
        switch (e.ValueKind)
        {
            case JsonValueKind.String:
                return Reads(() => e.GetString()) ? null : at;
            case JsonValueKind.Array:
                int i = 0;
                foreach (var item in e.EnumerateArray())
                {
                    if (Walk(item, $"{at}[{i++}]") is { } bad)
                    {
                        return bad;
                    }
                }

                return null;
            case JsonValueKind.Object:
                foreach (var p in e.EnumerateObject())
                {
                    string? name = null;
                    if (!Reads(() => name = p.Name))
                    {
                        return at + ".<name>";
                    }

                    if (Walk(p.Value, $"{at}.{Shorten(name!)}") is { } bad)
                    {
                        return bad;
                    }
                }

                return null;
            default:
                return null;
        }
    }

    private static string Shorten(string name) => name.Length <= 40 ? name : name[..40] + "...";

    private static bool Reads(Func<string?> read)
    {
        try
        {
            _ = read();
            return true;
        }
        catch (InvalidOperationException)
        {
            return false;
        }
    }
}
