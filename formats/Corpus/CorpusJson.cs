using System.Text;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Core.Text;
using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// Reads and writes corpus files (docs/corpus-format.md): readable JSON, hex cell ids, float32 values printed so
/// they round-trip, non-finite values as the strings "NaN", "Infinity", "-Infinity". Reading validates everything
/// and reports the first problem with its JSON path; it never returns a half-read entry.
/// </summary>
public static class CorpusJson
{
    /// <summary>The value of the <c>format</c> field.</summary>
    public const string FormatName = "acphys-case";

    /// <summary>The longest title a case file may carry, in characters (issue 19: a 50 MB title was echoed to stdout).</summary>
    public const int MaxTitle = 4096;

    private const string EnterAndBack = "enter-and-back";

    private static readonly JsonWriterOptions WriterOptions = new() { Indented = true, Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping };

    /// <summary>Serialises an entry.</summary>
    /// <param name="entry">The entry.</param>
    /// <returns>The JSON text, ending in a newline.</returns>
    public static string Write(CorpusEntry entry)
    {
        using var buffer = new MemoryStream();
        using (var w = new Utf8JsonWriter(buffer, WriterOptions))
        {
            w.WriteStartObject();
            w.WriteString("format", FormatName);
            w.WriteNumber("version", CorpusEntry.CurrentVersion);
            w.WriteString("kind", entry.Kind);
            w.WriteString("title", entry.Title);
            if (entry.Invariant is not null)
            {
                w.WriteString("invariant", entry.Invariant);
            }

            w.WriteString("foundBy", entry.FoundBy);
            if (entry.Seed is not null)
            {
                w.WriteString("seed", entry.Seed);
            }

            if (entry.Mode is { IsRetail: false } mode)
            {
                WriteMode(w, mode);
            }

            w.WriteStartArray("catches");
            foreach (var f in entry.Catches)
            {
                w.WriteStringValue(f);
            }

            w.WriteEndArray();
            if (entry.Parts is { } parts)
            {
                PartsJson.Write(w, parts);
            }
            else if (entry.Query is { } query)
            {
                QueryJson.Write(w, query);
            }
            else if (entry.SceneWalk is { } sw)
            {
                w.WritePropertyName("scene");
                AcPhys.Formats.Scenes.SceneJson.WriteValue(w, sw.Scene);
                WalkJson.Write(w, sw.Walk);
                if (sw.Route == SceneRoute.EnterAndBack)
                {
                    w.WriteString("route", EnterAndBack); // the one route an invariant reads (ENTER-EXIT)
                }
            }
            else if (entry.Walk is { } walk)
            {
                WalkJson.Write(w, walk);
                if (entry.Recorded is { } recorded)
                {
                    RecordedJson.Write(w, recorded);
                }
            }
            else
            {
                var c = entry.Case ?? throw new ArgumentException("an entry needs a case or a walk", nameof(entry));
                w.WriteStartObject("case");
                w.WriteString("cell", CellIdText.Format(c.Cell));
                WriteFloat(w, "x", c.X);
                WriteFloat(w, "y", c.Y);
                w.WriteStartArray("lcoord");
                w.WriteNumberValue(c.Lcoord.X);
                w.WriteNumberValue(c.Lcoord.Y);
                w.WriteEndArray();
                w.WriteEndObject();
            }

            w.WriteEndObject();
        }

        return Encoding.UTF8.GetString(buffer.ToArray()) + "\n";
    }

    /// <summary>Parses an entry.</summary>
    /// <param name="json">The text.</param>
    /// <param name="source">A name for messages (the file path).</param>
    /// <returns>The entry.</returns>
    /// <exception cref="InputFormatException">The text is not a valid corpus entry.</exception>
    public static CorpusEntry Read(string json, string source)
    {
        JsonDocument doc;
        try
        {
            doc = JsonDocument.Parse(json, new JsonDocumentOptions { CommentHandling = JsonCommentHandling.Disallow, MaxDepth = 24 });
        }
        catch (JsonException e)
        {
            throw new InputFormatException($"{source}: not valid JSON: {e.Message}");
        }

        using (doc)
        {
            var root = doc.RootElement;
            Require(root.ValueKind == JsonValueKind.Object, source, "$", "expected an object");
            if (JsonStrings.FirstUnreadable(root, "$") is { } bad)
            {
                // Before the duplicate-key search, which reads every property name (a lone surrogate name throws).
                throw new InputFormatException($"{source}: {bad}: not valid text (invalid UTF-8 or a lone UTF-16 surrogate)");
            }

            if (JsonKeys.FirstDuplicate(root) is { } duplicate)
            {
                throw new InputFormatException($"{source}: {JsonKeys.Message(duplicate)}");
            }

            Require(Str(root, "format", source) == FormatName, source, "$.format", $"expected \"{FormatName}\"");
            var version = Prop(root, "version", source);
            Require(version.ValueKind == JsonValueKind.Number && version.TryGetInt32(out int v) && v == CorpusEntry.CurrentVersion, source, "$.version", $"expected {CorpusEntry.CurrentVersion}");
            string kind = Str(root, "kind", source);
            Require(kind is "land" or "walk" or "scene-walk" or "parts" or "query", source, "$.kind", "expected \"land\" or \"walk\" (or \"scene-walk\", \"parts\", \"query\")");
            string title = Str(root, "title", source);
            Require(title.Length <= MaxTitle, source, "$.title", $"{title.Length} characters; at most {MaxTitle}");
            string foundBy = Str(root, "foundBy", source);
            Require(FinderNames.IsKnown(foundBy), source, "$.foundBy", FinderNames.Expected);
            string? invariant = OptStr(root, "invariant", source);
            string? seed = OptStr(root, "seed", source);
            var catches = new List<string>();
            if (root.TryGetProperty("catches", out var c))
            {
                Require(c.ValueKind == JsonValueKind.Array, source, "$.catches", "expected an array of fault ids");
                Refuse(AcPhys.Formats.Values.CatchList.Problem(c.GetArrayLength()), source, "$.catches");
                int i = 0;
                foreach (var item in c.EnumerateArray())
                {
                    Require(item.ValueKind == JsonValueKind.String, source, $"$.catches[{i}]", "expected a string");
                    catches.Add(Text(item, source, $"$.catches[{i}]"));
                    i++;
                }
            }

            var mode = root.TryGetProperty("mode", out var m) ? ReadMode(m, source) : null;
            var header = new CorpusEntry { Title = title, Invariant = invariant, FoundBy = foundBy, Seed = seed, Mode = mode, Catches = catches };
            Require(kind == "walk" || !root.TryGetProperty("recorded", out _), source, "$.recorded", "only a walk records a port's answers (kind \"walk\")");
            if (kind == "scene-walk")
            {
                var scene = AcPhys.Formats.Scenes.SceneJson.Read(Prop(root, "scene", source), source, "$.scene");

                string? route = OptStr(root, "route", source);
                Require(route is null or EnterAndBack, source, "$.route", $"expected \"{EnterAndBack}\" (the only route a stored scene walk names)");
                var sceneWalk = WalkJson.Read(Prop(root, "walk", source), source);
                Refuse(AcPhys.Formats.Values.SceneWalkStart.Problem(scene, sceneWalk.StartCell), source, "$.walk.start.cell");
                return header with { SceneWalk = new SceneWalk(scene, sceneWalk) { Route = route is null ? null : SceneRoute.EnterAndBack } };
            }

            if (kind == "query")
            {
                return header with { Query = QueryJson.Read(Prop(root, "query", source), source) };
            }

            if (kind == "parts")
            {
                return header with { Parts = PartsJson.Read(Prop(root, "parts", source), source) };
            }

            if (kind == "walk")
            {
                var walk = WalkJson.Read(Prop(root, "walk", source), source);
                var recorded = root.TryGetProperty("recorded", out var r) ? RecordedJson.Read(r, walk.Steps.Count + 1, source) : null;
                return header with { Walk = walk, Recorded = recorded };
            }

            var caseElement = Prop(root, "case", source);
            Require(caseElement.ValueKind == JsonValueKind.Object, source, "$.case", "expected an object");
            string cellText = Str(caseElement, "cell", source, "$.case");
            Require(CellIdText.TryParse(cellText, out var cell), source, "$.case.cell", $"expected \"0x\" and 8 hex digits, got \"{AcPhys.Formats.Values.InputQuote.Brief(cellText)}\"");
            float x = Float(caseElement, "x", source);
            float y = Float(caseElement, "y", source);
            var lc = Prop(caseElement, "lcoord", source, "$.case");
            Require(lc.ValueKind == JsonValueKind.Array && lc.GetArrayLength() == 2, source, "$.case.lcoord", "expected [x, y]");
            Require(lc[0].ValueKind == JsonValueKind.Number && lc[0].TryGetInt32(out int lx), source, "$.case.lcoord[0]", "expected a 32-bit integer");
            Require(lc[1].ValueKind == JsonValueKind.Number && lc[1].TryGetInt32(out int ly), source, "$.case.lcoord[1]", "expected a 32-bit integer");
            lx = lc[0].GetInt32();
            ly = lc[1].GetInt32();

            return header with { Case = new LandCase(cell, x, y, new Lcoord(lx, ly)) };
        }
    }

    /// <summary>Reads a corpus file.</summary>
    /// <param name="path">The file.</param>
    /// <returns>The entry.</returns>
    /// <exception cref="InputFormatException">The file cannot be read or is not valid.</exception>
    public static CorpusEntry ReadFile(string path)
    {
        string text;
        try
        {
            text = File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new InputFormatException($"{path}: cannot read: {e.Message}");
        }

        return Read(text, path);
    }

    // The mode: {"pick": "current-first", "fidelity": ["ace-keeps-stale-cells"], "fault": "trunc-floor"}, each optional.
    private static void WriteMode(Utf8JsonWriter w, CaseMode mode)
    {
        w.WriteStartObject("mode");
        if (mode.Pick is not null)
        {
            w.WriteString("pick", mode.Pick);
        }

        if (mode.Fidelity.Count > 0)
        {
            w.WriteStartArray("fidelity");
            foreach (string name in mode.Fidelity)
            {
                w.WriteStringValue(name);
            }

            w.WriteEndArray();
        }

        if (mode.Fault is not null)
        {
            w.WriteString("fault", mode.Fault);
        }

        w.WriteEndObject();
    }

    private static CaseMode ReadMode(JsonElement m, string source)
    {
        Require(m.ValueKind == JsonValueKind.Object, source, "$.mode", "expected an object with \"pick\", \"fidelity\" and \"fault\", each optional");
        foreach (var property in m.EnumerateObject())
        {
            Require(property.Name is "pick" or "fidelity" or "fault", source, "$.mode." + AcPhys.Formats.Values.InputQuote.Brief(property.Name), "unknown field (known: pick, fidelity, fault)");
        }

        string? pick = OptStr(m, "pick", source, "$.mode");
        Require(pick is null || (AcPhys.Contract.PickNames.TryParse(pick, out var policy) && policy == PickPolicy.CurrentFirst), source, "$.mode.pick", "expected \"current-first\" (retail is the default and is not stored)");
        var names = new List<string>();
        if (m.TryGetProperty("fidelity", out var f))
        {
            Require(f.ValueKind == JsonValueKind.Array && f.GetArrayLength() is > 0 and <= 16, source, "$.mode.fidelity", "expected an array of 1 to 16 deviation names");
            int i = 0;
            foreach (var item in f.EnumerateArray())
            {
                Require(item.ValueKind == JsonValueKind.String, source, $"$.mode.fidelity[{i}]", "expected a string");
                names.Add(Text(item, source, $"$.mode.fidelity[{i}]"));
                i++;
            }

            Require(AcPhys.Contract.FidelityNames.TryParse(names, out _, out _, out string? unknown), source, "$.mode.fidelity", $"unknown deviation \"{AcPhys.Formats.Values.InputQuote.Brief(unknown ?? string.Empty)}\" (known: {string.Join(", ", AcPhys.Contract.FidelityNames.Known)})");
        }

        string? fault = OptStr(m, "fault", source, "$.mode");
        Require(fault is null || fault.Length is > 0 and <= 100, source, "$.mode.fault", "expected a planted fault id (1 to 100 characters)");
        return new CaseMode(pick, names, fault);
    }

    /// <summary>Writes one sphere as <c>{"x","y","z","r"}</c>: a query's sphere (centre) or a walk's body sphere (offset).</summary>
    internal static void WriteBall(Utf8JsonWriter w, System.Numerics.Vector3 at, float radius)
    {
        w.WriteStartObject();
        WriteFloat(w, "x", at.X);
        WriteFloat(w, "y", at.Y);
        WriteFloat(w, "z", at.Z);
        WriteFloat(w, "r", radius);
        w.WriteEndObject();
    }

    internal static void WriteFloat(Utf8JsonWriter w, string name, float value)
    {
        if (float.IsFinite(value))
        {
            // Shortest round-trip text of the float32 itself, not of its double widening.
            w.WritePropertyName(name);
            w.WriteRawValue(FloatText.Format(value));
        }
        else
        {
            w.WriteString(name, FloatText.Format(value)); // NaN, Infinity or -Infinity
        }
    }

    internal static float Float(JsonElement parent, string name, string source, string at = "$.case")
    {
        var e = Prop(parent, name, source, at);
        _ = AcPhys.Formats.Values.Float32Json.TryRead(e, nonFiniteNames: true, out float f, out string? problem);
        Refuse(problem, source, at + "." + name);
        return f;
    }

    internal static JsonElement Prop(JsonElement parent, string name, string source, string at = "$")
    {
        if (!parent.TryGetProperty(name, out var e))
        {
            throw new InputFormatException($"{source}: {at}.{name}: missing");
        }

        return e;
    }

    internal static string Str(JsonElement parent, string name, string source, string at = "$")
    {
        var e = Prop(parent, name, source, at);
        Require(e.ValueKind == JsonValueKind.String, source, $"{at}.{name}", "expected a string");
        return Text(e, source, $"{at}.{name}");
    }

    private static string? OptStr(JsonElement parent, string name, string source, string at = "$")
    {
        if (!parent.TryGetProperty(name, out var e) || e.ValueKind == JsonValueKind.Null)
        {
            return null;
        }

        Require(e.ValueKind == JsonValueKind.String, source, $"{at}.{name}", "expected a string");
        return Text(e, source, $"{at}.{name}");
    }

    /// <summary>
    /// Reads a JSON string. JsonDocument accepts strings it cannot turn into .NET text (invalid UTF-8 bytes, a lone
    /// surrogate escape such as "\ud800") and only GetString throws, with InvalidOperationException; found by the
    /// walk-json fuzz target. Here that is a format error like any other.
    /// </summary>
    internal static string Text(JsonElement e, string source, string path)
    {
        try
        {
            return e.GetString()!;
        }
        catch (InvalidOperationException)
        {
            throw new InputFormatException($"{source}: {path}: not valid text (invalid UTF-8 or a lone UTF-16 surrogate)");
        }
    }

    /// <summary>Refuses a value the shared rules (formats/Values) found a problem with.</summary>
    internal static void Refuse(string? problem, string source, string path)
    {
        if (problem is not null)
        {
            throw new InputFormatException($"{source}: {path}: {problem}");
        }
    }

    internal static void Require(bool condition, string source, string path, string message)
    {
        if (!condition)
        {
            throw new InputFormatException($"{source}: {path}: {message}");
        }
    }
}
