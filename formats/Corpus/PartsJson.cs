using System.Numerics;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Core.Text;
using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// The <c>parts</c> array of a corpus file of kind <c>parts</c> (docs/corpus-format.md): one object per part, the
/// first being the anchor, <c>{"cell","origin":{"x","y","z"},"rotation":{"w","x","y","z"},"min":{…},"max":{…},"radius","always2d"}</c>,
/// floats as round-trip text. Every value must be finite: a parts file is an object's real parts.
/// </summary>
internal static class PartsJson
{
    /// <summary>Largest number of parts a file may hold (bounded input).</summary>
    public const int MaxParts = AcPhys.Formats.Values.PartBounds.MaxParts;

    /// <summary>Writes the query as the property <c>parts</c>.</summary>
    /// <param name="w">The writer, inside the entry object.</param>
    /// <param name="c">The query.</param>
    public static void Write(Utf8JsonWriter w, PartsCase c)
    {
        ArgumentNullException.ThrowIfNull(w);
        ArgumentNullException.ThrowIfNull(c);
        w.WriteStartArray("parts");
        foreach (var p in c.Parts)
        {
            w.WriteStartObject();
            w.WriteString("cell", CellIdText.Format(p.Cell));
            WriteVector(w, "origin", p.Frame.Origin);
            w.WriteStartObject("rotation");
            CorpusJson.WriteFloat(w, "w", p.Frame.Rotation.W);
            CorpusJson.WriteFloat(w, "x", p.Frame.Rotation.X);
            CorpusJson.WriteFloat(w, "y", p.Frame.Rotation.Y);
            CorpusJson.WriteFloat(w, "z", p.Frame.Rotation.Z);
            w.WriteEndObject();
            WriteVector(w, "min", p.Bounds.Min);
            WriteVector(w, "max", p.Bounds.Max);
            CorpusJson.WriteFloat(w, "radius", p.Radius);
            w.WriteBoolean("always2d", p.Always2D);
            w.WriteEndObject();
        }

        w.WriteEndArray();
    }

    /// <summary>Reads and validates a <c>parts</c> array.</summary>
    /// <param name="e">The <c>parts</c> element.</param>
    /// <param name="source">File name for messages.</param>
    /// <returns>The query.</returns>
    /// <exception cref="InputFormatException">Any defect, with its JSON path.</exception>
    public static PartsCase Read(JsonElement e, string source)
    {
        CorpusJson.Require(e.ValueKind == JsonValueKind.Array && e.GetArrayLength() is > 0 and <= MaxParts, source, "$.parts", $"expected an array of 1 to {MaxParts} parts (the first is the anchor)");
        var parts = new List<Part>();
        int i = 0;
        foreach (var p in e.EnumerateArray())
        {
            string at = $"$.parts[{i}]";
            CorpusJson.Require(p.ValueKind == JsonValueKind.Object, source, at, "expected an object");
            string cellText = CorpusJson.Str(p, "cell", source, at);
            CorpusJson.Require(CellIdText.TryParse(cellText, out var cell), source, at + ".cell", $"expected \"0x\" and 8 hex digits, got \"{AcPhys.Formats.Values.InputQuote.Brief(cellText)}\"");
            var origin = ReadVector(p, "origin", source, at);
            var r = Obj(p, "rotation", source, at);
            var rotation = new Quaternion(Finite(r, "x", source, at + ".rotation"), Finite(r, "y", source, at + ".rotation"), Finite(r, "z", source, at + ".rotation"), Finite(r, "w", source, at + ".rotation"));
            CorpusJson.Require(Math.Abs(rotation.Length() - 1) <= 1e-3f, source, at + ".rotation", "expected a unit quaternion (length 1 within 1e-3)");
            var min = ReadVector(p, "min", source, at);
            var max = ReadVector(p, "max", source, at);
            CorpusJson.Require(min.X <= max.X && min.Y <= max.Y && min.Z <= max.Z, source, at + ".min", "every component must be ≤ the same component of max");
            float radius = CorpusJson.Float(p, "radius", source, at);
            CorpusJson.Refuse(AcPhys.Formats.Values.SphereRadius.Problem(radius), source, at + ".radius");
            var flag = CorpusJson.Prop(p, "always2d", source, at);
            CorpusJson.Require(flag.ValueKind is JsonValueKind.True or JsonValueKind.False, source, at + ".always2d", "expected true or false");
            var part = new Part(cell, new Frame(origin, rotation), new Box(min, max), radius, flag.GetBoolean());
            if (AcPhys.Formats.Values.PartBounds.Problem(part, parts.Count == 0 ? part : parts[0]) is var (field, problem))
            {
                CorpusJson.Refuse(problem, source, at + "." + field);
            }

            parts.Add(part);
            i++;
        }

        return new PartsCase(parts);
    }

    private static void WriteVector(Utf8JsonWriter w, string name, Vector3 v)
    {
        w.WriteStartObject(name);
        CorpusJson.WriteFloat(w, "x", v.X);
        CorpusJson.WriteFloat(w, "y", v.Y);
        CorpusJson.WriteFloat(w, "z", v.Z);
        w.WriteEndObject();
    }

    private static Vector3 ReadVector(JsonElement parent, string name, string source, string at)
    {
        var v = Obj(parent, name, source, at);
        string path = at + "." + name;
        return new Vector3(Finite(v, "x", source, path), Finite(v, "y", source, path), Finite(v, "z", source, path));
    }

    private static JsonElement Obj(JsonElement parent, string name, string source, string at)
    {
        var v = CorpusJson.Prop(parent, name, source, at);
        CorpusJson.Require(v.ValueKind == JsonValueKind.Object, source, at + "." + name, "expected an object");
        return v;
    }

    private static float Finite(JsonElement parent, string name, string source, string at)
    {
        float v = CorpusJson.Float(parent, name, source, at);
        CorpusJson.Require(float.IsFinite(v), source, at + "." + name, "parts values must be finite");
        return v;
    }
}
