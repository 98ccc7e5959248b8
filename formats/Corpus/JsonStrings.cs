using System.Text.Json;

namespace AcPhys.Spec.Corpus;

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
        switch (e.ValueKind)
        {
            case JsonValueKind.String:
                return Reads(() => e.GetString()) ? null : at;
            case JsonValueKind.Array:
                int i = 0;
                foreach (var item in e.EnumerateArray())
                {
                    if (FirstUnreadable(item, $"{at}[{i++}]") is { } bad)
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

                    if (FirstUnreadable(p.Value, $"{at}.{Shorten(name!)}") is { } bad)
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
