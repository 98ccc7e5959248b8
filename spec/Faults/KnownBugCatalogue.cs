using System.Text.Json;

namespace AcPhys.Spec.Faults;

/// <summary>
/// The known-bug catalogue: the JSON files of mutation/known-bugs/, embedded in this assembly at build time, so the
/// CLI and the tests read the same entries from anywhere. Format (docs/bite.md): one object per file with
/// <c>format</c> = "acphys-known-bug", <c>id</c> (= the file name), <c>title</c>, <c>story</c>, <c>source</c>,
/// <c>fault</c>, <c>caughtBy</c> (array) and optionally <c>pendingOn</c>.
/// </summary>
public static class KnownBugCatalogue
{
    /// <summary>The value of the <c>format</c> field.</summary>
    public const string FormatName = "acphys-known-bug";

    private const string ResourcePrefix = "AcPhys.Spec.KnownBugs.";

    private static readonly Lazy<IReadOnlyList<KnownBug>> Entries = new(Load);

    private static readonly HashSet<string> Fields = ["format", "id", "title", "story", "source", "fault", "caughtBy", "pendingOn"];

    /// <summary>Gets every entry, ordered by id.</summary>
    /// <exception cref="FormatException">An embedded file is malformed (the message names it).</exception>
    public static IReadOnlyList<KnownBug> All => Entries.Value;

    /// <summary>Finds an entry by id (case-insensitive).</summary>
    /// <param name="id">The id.</param>
    /// <returns>The entry, or null.</returns>
    public static KnownBug? Find(string id) => All.FirstOrDefault(b => string.Equals(b.Id, id, StringComparison.OrdinalIgnoreCase));

    /// <summary>Parses one catalogue file.</summary>
    /// <param name="fileName">The file name (its id must match the <c>id</c> field).</param>
    /// <param name="json">The text.</param>
    /// <returns>The entry.</returns>
    /// <exception cref="FormatException">The text is not a valid entry; the message names the file and the field.</exception>
    public static KnownBug Parse(string fileName, string json)
    {
        try
        {
            using var doc = JsonDocument.Parse(json);
            var root = doc.RootElement;
            if (root.ValueKind != JsonValueKind.Object)
            {
                throw Bad(fileName, "the file must hold one JSON object");
            }

            if (Text(root, "format", fileName) != FormatName)
            {
                throw Bad(fileName, $"format must be \"{FormatName}\"");
            }

            string id = Text(root, "id", fileName);
            if (!string.Equals(id + ".json", Path.GetFileName(fileName), StringComparison.Ordinal))
            {
                throw Bad(fileName, $"id \"{id}\" must equal the file name without .json");
            }

            if (!root.TryGetProperty("caughtBy", out var catchers) || catchers.ValueKind != JsonValueKind.Array || catchers.GetArrayLength() == 0)
            {
                throw Bad(fileName, "caughtBy must be a non-empty array of invariant IDs");
            }

            var caughtBy = catchers.EnumerateArray().Select(e => e.ValueKind == JsonValueKind.String && e.GetString() is { Length: > 0 } s
                ? s
                : throw Bad(fileName, "caughtBy must hold invariant IDs (strings)")).ToArray();
            string? pendingOn = root.TryGetProperty("pendingOn", out _) ? Text(root, "pendingOn", fileName) : null;
            foreach (var field in root.EnumerateObject())
            {
                if (!Fields.Contains(field.Name))
                {
                    throw Bad(fileName, $"unknown field \"{field.Name}\"");
                }
            }

            return new KnownBug(id, Text(root, "title", fileName), Text(root, "story", fileName), Text(root, "source", fileName), Text(root, "fault", fileName), caughtBy, pendingOn);
        }
        catch (JsonException e)
        {
            throw Bad(fileName, "not valid JSON: " + e.Message);
        }
    }

    private static IReadOnlyList<KnownBug> Load()
    {
        var assembly = typeof(KnownBugCatalogue).Assembly;
        var bugs = new List<KnownBug>();
        foreach (var name in assembly.GetManifestResourceNames().Where(n => n.StartsWith(ResourcePrefix, StringComparison.Ordinal)))
        {
            using var stream = assembly.GetManifestResourceStream(name)!;
            using var reader = new StreamReader(stream);
            bugs.Add(Parse(name[ResourcePrefix.Length..], reader.ReadToEnd()));
        }

        return [.. bugs.OrderBy(b => b.Id, StringComparer.Ordinal)];
    }

    private static string Text(JsonElement root, string field, string fileName) =>
        root.TryGetProperty(field, out var v) && v.ValueKind == JsonValueKind.String && v.GetString() is { Length: > 0 } s
            ? s
            : throw Bad(fileName, $"{field} must be a non-empty string");

    private static FormatException Bad(string fileName, string message) => new($"known-bug catalogue, {fileName}: {message}");
}
