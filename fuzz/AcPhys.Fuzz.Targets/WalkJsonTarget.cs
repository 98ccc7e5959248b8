using System.Text.Json;
using AcPhys.Formats.Corpus;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>walk-json</c> parser target: bytes → a JSON document (syntax errors are not the walk reader's concern) →
/// <see cref="WalkJson.Read"/> on its root, the <c>walk</c> object of a file.
/// </summary>
public sealed class WalkJsonTarget : ParserTarget
{
    /// <inheritdoc/>
    public override string Name => "walk-json";

    /// <inheritdoc/>
    public override string Description => "WalkJson.Read on any JSON value; only InputFormatException may escape";

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = ParserSeeds.Entries
        .Where(e => e.Value.Walk is not null)
        .ToDictionary(e => e.Key, e => WalkObject(CorpusJson.Write(e.Value)));

    /// <inheritdoc/>
    protected override CorpusEntry? Read(ReadOnlySpan<byte> data)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(data.ToArray(), new JsonDocumentOptions { MaxDepth = 16 });
        }
        catch (JsonException)
        {
            return null;
        }

        using (doc)
        {
            return new CorpusEntry { Title = "walk", FoundBy = "fuzz", Walk = WalkJson.Read(doc.RootElement, "fuzz") };
        }
    }

    private static byte[] WalkObject(string entryJson)
    {
        using var doc = JsonDocument.Parse(entryJson);
        return System.Text.Encoding.UTF8.GetBytes(doc.RootElement.GetProperty("walk").GetRawText());
    }
}
