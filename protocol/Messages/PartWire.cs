using System.Numerics;
using System.Text.Json;
using AcPhys.Core;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// The encoding of a part for the optional <c>outside_cells_parts</c> extension:
/// <c>{cell, origin:{x,y,z}, rotation:{x,y,z,w}, min:{x,y,z}, max:{x,y,z}, r, always2d}</c>.
/// </summary>
internal static class PartWire
{
    /// <summary>Writes parts as an array.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name.</param>
    /// <param name="parts">The parts.</param>
    public static void WriteParts(Utf8JsonWriter w, string name, IReadOnlyList<Part> parts)
    {
        w.WriteStartArray(name);
        foreach (var p in parts)
        {
            w.WriteStartObject();
            Wire.WriteCell(w, "cell", p.Cell);
            Wire.WriteVector(w, "origin", p.Frame.Origin);

            // The rotation, box and radius repeat from step to step of a walk: their texts are kept (FloatTexts).
            w.WriteStartObject("rotation"u8);
            FloatTexts.Write(w, "x"u8, p.Frame.Rotation.X);
            FloatTexts.Write(w, "y"u8, p.Frame.Rotation.Y);
            FloatTexts.Write(w, "z"u8, p.Frame.Rotation.Z);
            FloatTexts.Write(w, "w"u8, p.Frame.Rotation.W);
            w.WriteEndObject();
            FloatTexts.WriteVector(w, "min"u8, p.Bounds.Min);
            FloatTexts.WriteVector(w, "max"u8, p.Bounds.Max);
            FloatTexts.Write(w, "r"u8, p.Radius);
            w.WriteBoolean("always2d", p.Always2D);
            w.WriteEndObject();
        }

        w.WriteEndArray();
    }

    /// <summary>Reads parts.</summary>
    /// <param name="obj">The request object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The parts.</returns>
    public static Part[] ReadParts(JsonElement obj, string name)
    {
        var array = Wire.Field(obj, name);
        if (array.ValueKind != JsonValueKind.Array)
        {
            throw new WireException($"field \"{name}\" must be an array of parts");
        }

        if (AcPhys.Formats.Values.PartBounds.CountProblem(array.GetArrayLength()) is string count)
        {
            throw new WireException($"field \"{name}\": {count}");
        }

        var parts = array.EnumerateArray().Select(ReadPart).ToArray();
        for (int i = 0; i < parts.Length; i++)
        {
            if (AcPhys.Formats.Values.PartBounds.Problem(parts[i], parts[0]) is var (field, problem))
            {
                throw new WireException($"field \"{name}[{i}].{(field == "radius" ? "r" : field)}\": {problem}"); // bounded work (issue 28)
            }
        }

        return parts;
    }

    private static Part ReadPart(JsonElement p)
    {
        var q = Wire.Field(p, "rotation");
        var rotation = new Quaternion(Wire.ReadFloat(q, "x"), Wire.ReadFloat(q, "y"), Wire.ReadFloat(q, "z"), Wire.ReadFloat(q, "w"));
        return new Part(
            Wire.ReadCell(p, "cell"),
            new Frame(Wire.ReadVector(p, "origin"), rotation),
            new Box(Wire.ReadVector(p, "min"), Wire.ReadVector(p, "max")),
            Wire.ReadRadius(p, "r"),
            Wire.ReadBool(p, "always2d"));
    }
}
