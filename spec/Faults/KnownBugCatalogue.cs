using System.Text.Json;

namespace AcPhys.Spec.Faults;

/// <summary>
/// The known-bug catalogue: the JSON files of mutation/known-bugs/, embedded in this assembly at build time, so the
/// CLI and the tests read the same entries from anywhere. An entry is derived from its planted fault
/// (<see cref="PlantedFaults"/>): a file says only what the fault does not (docs/bite.md). Format: one object per file
/// with <c>format</c> = "acphys-known-bug", <c>id</c> (= the file name), <c>source</c>, and optionally <c>fault</c>
/// (default: the id), <c>title</c> (default: the fault's, sentence-cased), <c>story</c> (default: the fault's) and
/// <c>pendingOn</c>. The invariants expected to catch it are always the fault's <see cref="PlantedFault.CaughtBy"/>.
/// </summary>
public static class KnownBugCatalogue
{
    /// <summary>The value of the <c>format</c> field.</summary>
    public const string FormatName = "acphys-known-bug";

    private const string ResourcePrefix = "AcPhys.Spec.KnownBugs.";

    private static readonly Lazy<IReadOnlyList<KnownBug>> Entries = new(Load);

    private static readonly HashSet<string> Fields = ["format", "id", "title", "story", "source", "fault", "pendingOn"];

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

            if (root.TryGetProperty("caughtBy", out _))
            {
                // Derived, never restated: a copy could drift from the fault the bite runs (issue 25).
                throw Bad(fileName, "caughtBy is not a field: the catchers are the planted fault's CaughtBy (spec/Faults); remove it");
            }

            foreach (var field in root.EnumerateObject())
            {
                if (!Fields.Contains(field.Name))
                {
                    throw Bad(fileName, $"unknown field \"{field.Name}\"");
                }
            }

            string faultId = root.TryGetProperty("fault", out _) ? Text(root, "fault", fileName) : id;
            var fault = PlantedFaults.Find(faultId);
            string? pendingOn = root.TryGetProperty("pendingOn", out _) ? Text(root, "pendingOn", fileName) : null;
            string title = Own(root, "title", fileName, fault is null ? null : SentenceCase(fault.Title));
            string story = Own(root, "story", fileName, fault?.Story);
            return new KnownBug(id, title, story, Text(root, "source", fileName), faultId, fault?.CaughtBy ?? [], pendingOn);
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

    /// <summary>The entry's own text for a field, or the fault's when the file leaves it out (required when there is no fault yet).</summary>
    private static string Own(JsonElement root, string field, string fileName, string? fromFault) =>
        root.TryGetProperty(field, out _) || fromFault is null ? Text(root, field, fileName) : fromFault;

    private static string SentenceCase(string s) => s.Length == 0 ? s : char.ToUpperInvariant(s[0]) + s[1..];

    private static FormatException Bad(string fileName, string message) => new($"known-bug catalogue, {fileName}: {message}");
}
