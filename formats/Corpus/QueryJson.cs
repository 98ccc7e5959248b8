using System.Numerics;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Core.Text;
using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// The <c>query</c> member of a corpus entry of kind <c>query</c>: one open-land query (<see cref="OutdoorCase"/>) exactly
/// as it was asked, the start cell any 32-bit id and every number any float32 (NaN and infinities as strings), so a
/// generated query from id 0, a malformed id or a non-finite centre is stored as found.
/// </summary>
internal static class QueryJson
{
    /// <summary>Writes the <c>query</c> member.</summary>
    /// <param name="w">The writer, inside the entry object.</param>
    /// <param name="q">The query.</param>
    public static void Write(Utf8JsonWriter w, OutdoorCase q)
    {
        w.WriteStartObject("query");
        w.WriteString("cell", CellIdText.Format(q.Cell));
        w.WriteStartObject("origin");
        CorpusJson.WriteFloat(w, "x", q.Origin.X);
        CorpusJson.WriteFloat(w, "y", q.Origin.Y);
        CorpusJson.WriteFloat(w, "z", q.Origin.Z);
        w.WriteEndObject();
        w.WriteStartArray("spheres");
        foreach (var s in q.Spheres)
        {
            CorpusJson.WriteBall(w, s.Center, s.Radius);
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>Reads the <c>query</c> member.</summary>
    /// <param name="e">The member's value.</param>
    /// <param name="source">The file, for messages.</param>
    /// <returns>The query.</returns>
    /// <exception cref="InputFormatException">The member is malformed (the message names the path).</exception>
    public static OutdoorCase Read(JsonElement e, string source)
    {
        CorpusJson.Require(e.ValueKind == JsonValueKind.Object, source, "$.query", "expected an object");
        string cellText = CorpusJson.Str(e, "cell", source, "$.query");
        CorpusJson.Require(CellIdText.TryParse(cellText, out var cell), source, "$.query.cell", $"expected \"0x\" and 8 hex digits, got \"{AcPhys.Formats.Values.InputQuote.Brief(cellText)}\"");
        var origin = CorpusJson.Prop(e, "origin", source, "$.query");
        CorpusJson.Require(origin.ValueKind == JsonValueKind.Object, source, "$.query.origin", "expected an object");
        var at = new Vector3(
            CorpusJson.Float(origin, "x", source, "$.query.origin"),
            CorpusJson.Float(origin, "y", source, "$.query.origin"),
            CorpusJson.Float(origin, "z", source, "$.query.origin"));
        var list = CorpusJson.Prop(e, "spheres", source, "$.query");
        CorpusJson.Require(list.ValueKind == JsonValueKind.Array, source, "$.query.spheres", "expected an array of spheres");
        CorpusJson.Refuse(AcPhys.Formats.Values.SphereList.Problem(list.GetArrayLength(), 0), source, "$.query.spheres");
        var spheres = new List<Sphere>();
        int i = 0;
        foreach (var s in list.EnumerateArray())
        {
            string path = $"$.query.spheres[{i}]";
            CorpusJson.Require(s.ValueKind == JsonValueKind.Object, source, path, "expected an object");
            spheres.Add(new Sphere(
                new Vector3(CorpusJson.Float(s, "x", source, path), CorpusJson.Float(s, "y", source, path), CorpusJson.Float(s, "z", source, path)),
                CorpusJson.Float(s, "r", source, path)));
            i++;
        }

        return new OutdoorCase(cell, spheres) { Origin = at };
    }
}
