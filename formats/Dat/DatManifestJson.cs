using System.Globalization;
using System.Text;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Core.Text;
using AcPhys.Formats.Corpus;

namespace AcPhys.Formats.Dat;

/// <summary>Writes and strictly reads manifest.json (docs/dat-scenes.md, "Manifest"); errors name the JSON path.</summary>
public static class DatManifestJson
{
    private const int MaxItems = 100_000;

    /// <summary>Serialises a manifest.</summary>
    /// <param name="m">The manifest.</param>
    /// <returns>The text, ending in a newline.</returns>
    public static string Write(DatManifest m)
    {
        using var buffer = new MemoryStream();
        using (var w = new Utf8JsonWriter(buffer, new JsonWriterOptions { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping }))
        {
            Write(w, m);
        }

        return Encoding.UTF8.GetString(buffer.ToArray()) + "\n";
    }

    /// <summary>Writes a manifest as one JSON object value (the writer decides indentation: a protocol line is compact).</summary>
    /// <param name="w">The writer, where a value may go.</param>
    /// <param name="m">The manifest.</param>
    public static void Write(Utf8JsonWriter w, DatManifest m)
    {
        w.WriteStartObject();
        w.WriteString("format", DatManifest.FormatName);
        w.WriteNumber("version", DatManifest.CurrentVersion);
        w.WriteString("title", m.Title);
        w.WriteString("source", m.Source);
        w.WriteStartArray("records");
        foreach (var r in m.Records)
        {
            w.WriteStartObject();
            w.WriteString("file", r.File);
            w.WriteString("id", RecordIds.Text(r.Id));
            w.WriteString("dat", r.PortalDat ? "portal" : "cell");
            w.WriteString("type", r.Type.ToString());
            w.WriteEndObject();
        }

        w.WriteEndArray();
        Strings(w, "blocks", m.Blocks.Select(b => b.ToString()));
        Strings(w, "unloadedBlocks", m.UnloadedBlocks.Select(b => b.ToString()));
        Strings(w, "unloadedCells", m.UnloadedCells.Select(CellIdText.Format));
        w.WriteStartArray("visibleElsewhere");
        foreach (var (cell, visible) in m.VisibleElsewhere)
        {
            w.WriteStartObject();
            w.WriteString("cell", CellIdText.Format(cell));
            Strings(w, "visible", visible.Select(CellIdText.Format));
            w.WriteEndObject();
        }

        w.WriteEndArray();
        if (m.Header is { } h)
        {
            w.WriteStartObject("corpus");
            if (h.Invariant is not null)
            {
                w.WriteString("invariant", h.Invariant);
            }

            w.WriteString("foundBy", h.FoundBy);
            if (h.Seed is not null)
            {
                w.WriteString("seed", h.Seed);
            }

            Strings(w, "catches", h.Catches);
            w.WriteEndObject();
        }

        if (m.Walk is { } walk)
        {
            WalkJson.Write(w, walk);
        }

        w.WriteEndObject();
    }

    /// <summary>Parses a manifest held in a parsed document (a <c>load_scene</c> request's <c>dat.manifest</c>).</summary>
    /// <param name="element">The manifest object.</param>
    /// <param name="source">A name for messages.</param>
    /// <returns>The manifest.</returns>
    /// <exception cref="InputFormatException">Any defect, with its JSON path: the messages <see cref="Read(string, string)"/> gives for the same text.</exception>
    public static DatManifest Read(JsonElement element, string source)
    {
        // Parse once (issue 26): a manifest inside an already parsed request is read in place. Only one nested beyond
        // what Read(string) parses (MaxDepth 24; generous margin here) takes the text path, so its refusal reads as before.
        if (Deeper(element, 16))
        {
            return Read(element.GetRawText(), source);
        }

        return Parse(element, source);
    }

    /// <summary>Reads a manifest from its JSON text (manifest.json).</summary>
    /// <param name="json">The text.</param>
    /// <param name="source">A name for messages.</param>
    /// <returns>The manifest.</returns>
    /// <exception cref="InputFormatException">Not JSON, or any defect.</exception>
    public static DatManifest Read(string json, string source)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(json, new JsonDocumentOptions { MaxDepth = 24 });
        }
        catch (JsonException e)
        {
            throw new InputFormatException($"{source}: not valid JSON: {e.Message}");
        }

        using (doc)
        {
            return Parse(doc.RootElement, source);
        }
    }

    // Whether the element nests deeper than `most` levels (stops at the first such branch; no enumerator allocated).
    private static bool Deeper(JsonElement e, int most)
    {
        if (most < 0)
        {
            return true;
        }

        switch (e.ValueKind)
        {
            case JsonValueKind.Object:
                foreach (var p in e.EnumerateObject())
                {
                    if (Deeper(p.Value, most - 1))
                    {
                        return true;
                    }
                }

                return most == 0;
            case JsonValueKind.Array:
                foreach (var v in e.EnumerateArray())
                {
                    if (Deeper(v, most - 1))
                    {
                        return true;
                    }
                }

                return most == 0;
            default:
                return false;
        }
    }

    private static DatManifest Parse(JsonElement root, string source)
    {
        void Require(bool ok, string path, string message)
        {
            if (!ok)
            {
                throw new InputFormatException($"{source}: {path}: {message}");
            }
        }

        Require(root.ValueKind == JsonValueKind.Object, "$", "expected an object");
        var names = new HashSet<string>();
        foreach (var p in root.EnumerateObject())
        {
            Require(names.Add(p.Name), "$." + p.Name, "duplicate key");
        }

        Require(Str(root, "format", source) == DatManifest.FormatName, "$.format", $"expected \"{DatManifest.FormatName}\"");
        Require(root.TryGetProperty("version", out var version) && version.ValueKind == JsonValueKind.Number && version.TryGetInt32(out int v) && v == DatManifest.CurrentVersion, "$.version", $"expected {DatManifest.CurrentVersion}");
        string title = Str(root, "title", source);
        string src = Str(root, "source", source);
        var records = new List<ManifestRecord>();
        var items = Items(root, "records", source);
        for (int i = 0; i < items.Count; i++)
        {
            // The paths and messages are spelt only when a check fails (issue 26: spelling them for every record was
            // most of this reader's time on a served gate).
            var e = items[i];
            if (e.ValueKind != JsonValueKind.Object)
            {
                throw Fail(source, RecordPath(i), "expected an object");
            }

            string idText = Str(e, "id", source, i);
            if (!(idText.StartsWith("0x", StringComparison.Ordinal) && idText.Length == 10 && uint.TryParse(idText.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out uint id)))
            {
                throw Fail(source, RecordPath(i) + ".id", $"expected \"0x\" and 8 hex digits, got \"{AcPhys.Formats.Values.InputQuote.Brief(idText)}\"");
            }

            string dat = Str(e, "dat", source, i);
            if (dat is not ("cell" or "portal"))
            {
                throw Fail(source, RecordPath(i) + ".dat", "expected \"cell\" or \"portal\"");
            }

            string type = Str(e, "type", source, i);
            if (!(Enum.TryParse<RecordType>(type, out var t) && Enum.IsDefined(t) && t.ToString() == type))
            {
                throw Fail(source, RecordPath(i) + ".type", $"expected one of {string.Join(", ", Enum.GetNames<RecordType>())}");
            }

            var record = new ManifestRecord(id, dat == "portal", t);
            if (Str(e, "file", source, i) != record.File)
            {
                throw Fail(source, RecordPath(i) + ".file", $"expected \"{record.File}\" (the id's 8 upper-case hex digits)");
            }

            records.Add(record);
        }

        var blocks = Blocks(root, "blocks", source);
        var unloadedBlocks = Blocks(root, "unloadedBlocks", source);
        var unloadedCells = Items(root, "unloadedCells", source).Select((x, i) => Cell(x, $"$.unloadedCells[{i}]", source)).ToList();
        var elsewhere = new List<(CellId, IReadOnlyList<CellId>)>();
        var ve = Items(root, "visibleElsewhere", source);
        for (int i = 0; i < ve.Count; i++)
        {
            string at = $"$.visibleElsewhere[{i}]";
            Require(ve[i].ValueKind == JsonValueKind.Object && ve[i].TryGetProperty("cell", out var c), at, "expected an object {\"cell\", \"visible\"}");
            var cell = Cell(ve[i].GetProperty("cell"), at + ".cell", source);
            Require(elsewhere.All(x => x.Item1 != cell), at + ".cell", $"{cell} is listed twice");
            elsewhere.Add((cell, [.. Items(ve[i], "visible", source, at).Select((x, k) => Cell(x, $"{at}.visible[{k}]", source))]));
        }

        CorpusEntry? header = null;
        if (root.TryGetProperty("corpus", out var corpus))
        {
            Require(corpus.ValueKind == JsonValueKind.Object, "$.corpus", "expected an object");
            var invariant = corpus.TryGetProperty("invariant", out _) ? Str(corpus, "invariant", source, "$.corpus") : null;
            var seed = corpus.TryGetProperty("seed", out _) ? Str(corpus, "seed", source, "$.corpus") : null;
            string foundBy = Str(corpus, "foundBy", source, "$.corpus");
            Require(FinderNames.IsKnown(foundBy), "$.corpus.foundBy", FinderNames.Expected);
            var catches = Items(corpus, "catches", source, "$.corpus").Select((x, i) => Text(x, $"$.corpus.catches[{i}]", source)).ToList();
            header = new CorpusEntry { Title = title, FoundBy = foundBy, Invariant = invariant, Seed = seed, Catches = catches };
        }

        var walk = root.TryGetProperty("walk", out var w) ? WalkJson.Read(w, source) : null;
        Require(walk is null || header is not null, "$.walk", "a walk needs the \"corpus\" header");
        return new DatManifest(title, src, records, blocks, unloadedBlocks, unloadedCells, elsewhere) { Header = header, Walk = walk };
    }

    private static List<JsonElement> Items(JsonElement parent, string name, string source, string at = "$")
    {
        if (!parent.TryGetProperty(name, out var e))
        {
            throw new InputFormatException($"{source}: {at}.{name}: missing");
        }

        if (e.ValueKind != JsonValueKind.Array || e.GetArrayLength() > MaxItems)
        {
            throw new InputFormatException($"{source}: {at}.{name}: expected an array of at most {MaxItems} items");
        }

        return [.. e.EnumerateArray()];
    }

    private static string Str(JsonElement parent, string name, string source, string at = "$")
    {
        if (!parent.TryGetProperty(name, out var e))
        {
            throw new InputFormatException($"{source}: {at}.{name}: missing");
        }

        return Text(e, $"{at}.{name}", source);
    }

    // A field of records[index]: its path is spelt only for a message.
    private static string Str(JsonElement parent, string name, string source, int index)
    {
        if (!parent.TryGetProperty(name, out var e))
        {
            throw new InputFormatException($"{source}: {RecordPath(index)}.{name}: missing");
        }

        // A readable string at once; anything else is read again by Text, with its path, for the message.
        return e.ValueKind == JsonValueKind.String && ValidText(e) is { } text ? text : Text(e, $"{RecordPath(index)}.{name}", source);
    }

    private static string RecordPath(int index) => string.Create(CultureInfo.InvariantCulture, $"$.records[{index}]");

    private static InputFormatException Fail(string source, string path, string message) => new($"{source}: {path}: {message}");

    private static string Text(JsonElement e, string path, string source)
    {
        if (e.ValueKind != JsonValueKind.String)
        {
            throw new InputFormatException($"{source}: {path}: expected a string");
        }

        try
        {
            return e.GetString()!;
        }
        catch (InvalidOperationException)
        {
            throw new InputFormatException($"{source}: {path}: not valid text (invalid UTF-8 or a lone surrogate)");
        }
    }

    private static List<LandblockId> Blocks(JsonElement root, string name, string source)
    {
        var items = Items(root, name, source);
        var blocks = new List<LandblockId>(items.Count);
        for (int i = 0; i < items.Count; i++)
        {
            var e = items[i];
            blocks.Add(e.ValueKind == JsonValueKind.String && ValidText(e) is { } text && TryBlock(text, out var block)
                ? block
                : Block(e, string.Create(CultureInfo.InvariantCulture, $"$.{name}[{i}]"), source)); // not a block: read again for its message
        }

        return blocks;
    }

    private static string? ValidText(JsonElement e)
    {
        try
        {
            return e.GetString();
        }
        catch (InvalidOperationException)
        {
            return null;
        }
    }

    private static bool TryBlock(string text, out LandblockId block)
    {
        ushort v = 0;
        bool ok = text.StartsWith("0x", StringComparison.Ordinal) && text.Length == 6 && ushort.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out v);
        block = new LandblockId(v);
        return ok;
    }

    private static LandblockId Block(JsonElement e, string path, string source)
    {
        string text = Text(e, path, source);
        if (!(text.StartsWith("0x", StringComparison.Ordinal) && text.Length == 6 && ushort.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out ushort v)))
        {
            throw new InputFormatException($"{source}: {path}: expected a block id \"0x\" and 4 hex digits, got \"{AcPhys.Formats.Values.InputQuote.Brief(text)}\"");
        }

        return new LandblockId(v);
    }

    private static CellId Cell(JsonElement e, string path, string source)
    {
        string text = Text(e, path, source);
        if (!CellIdText.TryParse(text, out var id))
        {
            throw new InputFormatException($"{source}: {path}: expected a cell id \"0x\" and 8 hex digits, got \"{AcPhys.Formats.Values.InputQuote.Brief(text)}\"");
        }

        return id;
    }

    private static void Strings(Utf8JsonWriter w, string name, IEnumerable<string> values)
    {
        w.WriteStartArray(name);
        foreach (var s in values)
        {
            w.WriteStringValue(s);
        }

        w.WriteEndArray();
    }
}
