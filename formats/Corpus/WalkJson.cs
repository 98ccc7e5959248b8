using System.Numerics;
using System.Text.Json;
using AcPhys.Core.Text;
using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// The <c>walk</c> object of a corpus file (docs/corpus-format.md):
/// <c>{"start":{"cell","x","y","z"},"body":[{"x","y","z","r"}],"steps":[[dx,dy],…]}</c>, floats as round-trip text.
/// </summary>
public static class WalkJson
{
    /// <summary>Largest number of steps or spheres a file may hold (bounded input; the sphere rule is <see cref="AcPhys.Formats.Values.SphereList"/>).</summary>
    public const int MaxItems = AcPhys.Formats.Values.SphereList.Max;

    /// <summary>Writes the walk as the property <c>walk</c>.</summary>
    /// <param name="w">The writer, inside the entry object.</param>
    /// <param name="walk">The walk.</param>
    public static void Write(Utf8JsonWriter w, Walk walk)
    {
        w.WriteStartObject("walk");
        w.WriteStartObject("start");
        w.WriteString("cell", CellIdText.Format(walk.StartCell));
        CorpusJson.WriteFloat(w, "x", walk.Start.X);
        CorpusJson.WriteFloat(w, "y", walk.Start.Y);
        CorpusJson.WriteFloat(w, "z", walk.Start.Z);
        w.WriteEndObject();
        w.WriteStartArray("body");
        foreach (var b in walk.Body)
        {
            CorpusJson.WriteBall(w, b.Offset, b.Radius);
        }

        w.WriteEndArray();
        w.WriteStartArray("steps");
        foreach (var s in walk.Steps)
        {
            w.WriteStartArray();
            w.WriteRawValue(FloatText.Format(s.X));
            w.WriteRawValue(FloatText.Format(s.Y));
            w.WriteEndArray();
        }

        w.WriteEndArray();
        w.WriteEndObject();
    }

    /// <summary>Reads and validates a walk object.</summary>
    /// <param name="e">The <c>walk</c> element.</param>
    /// <param name="source">File name for messages.</param>
    /// <param name="minSpheres">The fewest body spheres (<see cref="AcPhys.Formats.Values.SphereList"/>): 1 for every walk file today, because the walk invariants judge sphere 0 (an empty body has no containing cell on the reference; a protocol query, by contrast, may be empty and then reads its <c>origin</c>).</param>
    /// <returns>The walk.</returns>
    /// <exception cref="InputFormatException">Any defect, with its JSON path.</exception>
    public static Walk Read(JsonElement e, string source, int minSpheres = 1)
    {
        CorpusJson.Require(e.ValueKind == JsonValueKind.Object, source, "$.walk", "expected an object");
        var start = CorpusJson.Prop(e, "start", source, "$.walk");
        CorpusJson.Require(start.ValueKind == JsonValueKind.Object, source, "$.walk.start", "expected an object");
        string cellText = CorpusJson.Str(start, "cell", source, "$.walk.start");
        CorpusJson.Require(CellIdText.TryParse(cellText, out var cell), source, "$.walk.start.cell", $"expected \"0x\" and 8 hex digits, got \"{AcPhys.Formats.Values.InputQuote.Brief(cellText)}\"");
        var position = new Vector3(
            Finite(start, "x", source, "$.walk.start"),
            Finite(start, "y", source, "$.walk.start"),
            Finite(start, "z", source, "$.walk.start"));

        var body = CorpusJson.Prop(e, "body", source, "$.walk");
        CorpusJson.Require(body.ValueKind == JsonValueKind.Array, source, "$.walk.body", "expected an array of spheres");
        CorpusJson.Refuse(AcPhys.Formats.Values.SphereList.Problem(body.GetArrayLength(), minSpheres), source, "$.walk.body");
        var spheres = new List<BodySphere>();
        int i = 0;
        foreach (var b in body.EnumerateArray())
        {
            string at = $"$.walk.body[{i}]";
            CorpusJson.Require(b.ValueKind == JsonValueKind.Object, source, at, "expected an object");
            float r = CorpusJson.Float(b, "r", source, at);
            CorpusJson.Refuse(AcPhys.Formats.Values.SphereRadius.Problem(r), source, at + ".r");
            spheres.Add(new BodySphere(new Vector3(Finite(b, "x", source, at), Finite(b, "y", source, at), Finite(b, "z", source, at)), r));
            i++;
        }

        var stepsElement = CorpusJson.Prop(e, "steps", source, "$.walk");
        CorpusJson.Require(stepsElement.ValueKind == JsonValueKind.Array && stepsElement.GetArrayLength() <= MaxItems, source, "$.walk.steps", $"expected an array of at most {MaxItems} [dx, dy] pairs");
        var steps = new List<Vector2>();
        i = 0;
        foreach (var s in stepsElement.EnumerateArray())
        {
            string at = $"$.walk.steps[{i}]";
            CorpusJson.Require(s.ValueKind == JsonValueKind.Array && s.GetArrayLength() == 2, source, at, "expected [dx, dy]");
            steps.Add(new Vector2(Component(s[0], source, at + "[0]"), Component(s[1], source, at + "[1]")));
            i++;
        }

        return new Walk(cell, position, spheres, steps);
    }

    // Walk coordinates must be finite: a walk is a path a body can take (non-finite inputs are LandDefs cases).
    private static float Finite(JsonElement parent, string name, string source, string at)
    {
        float v = CorpusJson.Float(parent, name, source, at);
        CorpusJson.Require(float.IsFinite(v), source, at + "." + name, "walk coordinates must be finite");
        return v;
    }

    private static float Component(JsonElement e, string source, string path)
    {
        _ = AcPhys.Formats.Values.Float32Json.TryRead(e, nonFiniteNames: false, out float v, out string? problem);
        CorpusJson.Refuse(problem, source, path);
        return v;
    }
}
