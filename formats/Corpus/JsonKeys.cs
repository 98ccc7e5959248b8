using System.Text.Json;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// Finds a key given twice in one JSON object. System.Text.Json keeps the last silently, so a duplicated <c>kind</c> once
/// surfaced as a misleading "missing" elsewhere (issue 19); corpus files, scene files and protocol requests refuse it.
/// </summary>
internal static class JsonKeys
{
    /// <summary>Returns the JSON path of the first key that appears twice in one object (e.g. <c>$.walk.kind</c>), or null.</summary>
    /// <param name="element">The root to search.</param>
    /// <returns>The path of the second occurrence, or null when every object's keys are distinct.</returns>
    public static string? FirstDuplicate(JsonElement element) => Find(element, "$");

    /// <summary>Returns the message for a duplicate key found by <see cref="FirstDuplicate"/>, the same in every reader.</summary>
    /// <param name="path">The key's JSON path.</param>
    /// <returns>E.g. <c>$.walk.kind: duplicate key "kind" (each key once per object)</c>.</returns>
    public static string Message(string path) =>
        $"{path}: duplicate key \"{AcPhys.Formats.Values.InputQuote.Brief(path[(path.LastIndexOf('.') + 1)..])}\" (each key once per object)";

    private static string? Find(JsonElement element, string path)
    {
        switch (element.ValueKind)
        {
            case JsonValueKind.Object:
                var seen = new HashSet<string>(StringComparer.Ordinal);
                foreach (var property in element.EnumerateObject())
                {
                    string at = path + "." + property.Name;
                    if (!seen.Add(property.Name))
                    {
                        return at;
                    }

                    if (Find(property.Value, at) is { } inner)
                    {
                        return inner;
                    }
                }

                return null;
            case JsonValueKind.Array:
                int i = 0;
                foreach (var item in element.EnumerateArray())
                {
                    if (Find(item, $"{path}[{i}]") is { } inner)
                    {
                        return inner;
                    }

                    i++;
                }

                return null;
            default:
                return null;
        }
    }
}
