using System.Text.Json;

namespace AcPhys.Cli.Replay;

/// <summary>The input kinds <c>replay</c> knows, and the choice of one for a file.</summary>
internal static class ReplayInputs
{
    /// <summary>Gets every known input kind; the first is the default when a file does not say.</summary>
    public static IReadOnlyList<IReplayInput> All { get; } =
    [
        new KindReplay("land", "a corpus case (one LandDefs input)"),
        new KindReplay("walk", "a walk (start, body, steps)"),
        new KindReplay("scene-walk", "a walk in a scene (loaded blocks, buildings, env cells, portals)"),
        new KindReplay("parts", "a parts / bounding-box query (the first part anchors)"),
        new KindReplay("query", "one open-land query (cell, spheres, origin)"),
    ];

    /// <summary>
    /// Chooses the input for a file by its top-level <c>kind</c> field. A file that cannot be read, is not JSON or has
    /// no string <c>kind</c> goes to the default input, whose reader reports the precise problem.
    /// </summary>
    /// <param name="path">The file.</param>
    /// <returns>The input.</returns>
    /// <exception cref="UsageException">The file names a kind no input knows.</exception>
    public static IReplayInput For(string path)
    {
        string? kind = SniffKind(path);
        if (kind is null)
        {
            return All[0];
        }

        return All.FirstOrDefault(i => i.Kind == kind)
            ?? throw new UsageException($"{path}: $.kind: replay does not know kind \"{kind}\" (known: {string.Join(", ", All.Select(i => i.Kind))})");
    }

    private static string? SniffKind(string path)
    {
        try
        {
            using var stream = File.OpenRead(path);
            using var doc = JsonDocument.Parse(stream);
            return doc.RootElement.ValueKind == JsonValueKind.Object
                && doc.RootElement.TryGetProperty("kind", out var kind)
                && kind.ValueKind == JsonValueKind.String
                ? kind.GetString()
                : null;
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or JsonException or ArgumentException or InvalidOperationException)
        {
            return null;
        }
    }
}
