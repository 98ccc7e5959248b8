using System.Buffers;
using System.Numerics;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Core.Text;

namespace AcPhys.Protocol.Messages;

/// <summary>The field encodings of protocol v1: each value written and read one way for both ends (cell ids, float32, spheres, origins, find_cell answers).</summary>
public static partial class Wire
{
    /// <summary>Writes a cell id as <c>"0xAABBCCCC"</c>.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name.</param>
    /// <param name="id">The id.</param>
    public static void WriteCell(Utf8JsonWriter w, string name, CellId id)
    {
        Span<byte> text = stackalloc byte[CellTextBytes];
        w.WriteString(name, CellText(id, text));
    }

    /// <summary>Writes a float32 as the exact JSON number of its value, or a string for the non-finite values.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name.</param>
    /// <param name="v">The value.</param>
    public static void WriteFloat(Utf8JsonWriter w, string name, float v)
    {
        w.WritePropertyName(name);
        WriteFloatValue(w, v);
    }

    /// <summary>Writes a float32 field named by its UTF-8 bytes (a literal such as <c>"x"u8</c>: no name transcoded per field).</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name, UTF-8.</param>
    /// <param name="v">The value.</param>
    public static void WriteFloat(Utf8JsonWriter w, ReadOnlySpan<byte> name, float v)
    {
        w.WritePropertyName(name);
        WriteFloatValue(w, v);
    }

    /// <summary>Writes a float32 value (see <see cref="WriteFloat(Utf8JsonWriter, string, float)"/>).</summary>
    /// <param name="w">The writer.</param>
    /// <param name="v">The value.</param>
    public static void WriteFloatValue(Utf8JsonWriter w, float v)
    {
        if (float.IsNaN(v))
        {
            w.WriteStringValue("NaN");
        }
        else if (float.IsInfinity(v))
        {
            w.WriteStringValue(v > 0 ? "Infinity" : "-Infinity");
        }
        else if (v == 0 && float.IsNegative(v))
        {
            // Keep the sign of zero visible to readers that parse "-0" as the integer 0.
            w.WriteRawValue("-0.0");
        }
        else
        {
            // The double of a float32 is exact, and its shortest round-trip text reads back as the same double in any language.
            w.WriteNumberValue((double)v);
        }
    }

    /// <summary>Writes a list of cell ids.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name.</param>
    /// <param name="cells">The ids.</param>
    public static void WriteCells(Utf8JsonWriter w, string name, IReadOnlyList<CellId> cells)
    {
        w.WriteStartArray(name);
        Span<byte> text = stackalloc byte[CellTextBytes];
        for (int i = 0; i < cells.Count; i++)
        {
            w.WriteStringValue(CellText(cells[i], text));
        }

        w.WriteEndArray();
    }

    /// <summary>
    /// Writes a find_cell answer: <c>cells</c>, <c>containing</c> (null for none) and, when reported, the optional
    /// <c>loaded</c> (one boolean per cell; false = a load hint) and <c>hits_interior_cell</c>.
    /// </summary>
    /// <param name="w">The writer.</param>
    /// <param name="r">The answer.</param>
    public static void WriteFindCell(Utf8JsonWriter w, AcPhys.Contract.FindCellResult r)
    {
        WriteCells(w, "cells", r.Cells);
        if (r.Containing.IsNone)
        {
            w.WriteNull("containing");
        }
        else
        {
            WriteCell(w, "containing", r.Containing);
        }

        if (r.Loaded is { } loaded)
        {
            w.WriteStartArray("loaded");
            foreach (bool b in loaded)
            {
                w.WriteBooleanValue(b);
            }

            w.WriteEndArray();
        }

        if (r.HitsInteriorCell is bool hits)
        {
            w.WriteBoolean("hits_interior_cell", hits);
        }
    }

    /// <summary>Reads a find_cell answer (see <see cref="WriteFindCell"/>); the optional fields stay null when absent.</summary>
    /// <param name="a">The answer object.</param>
    /// <returns>The answer.</returns>
    /// <exception cref="WireException">A field is malformed, or <c>loaded</c> is not parallel to <c>cells</c>.</exception>
    public static AcPhys.Contract.FindCellResult ReadFindCell(JsonElement a)
    {
        var cells = ReadCells(a, "cells");
        bool[]? loaded = null;
        if (a.TryGetProperty("loaded", out var flags) && flags.ValueKind != JsonValueKind.Null)
        {
            if (flags.ValueKind != JsonValueKind.Array || flags.EnumerateArray().Any(e => e.ValueKind is not (JsonValueKind.True or JsonValueKind.False)))
            {
                throw new WireException("field \"loaded\" must be an array of booleans");
            }

            loaded = [.. flags.EnumerateArray().Select(e => e.GetBoolean())];
            if (loaded.Length != cells.Length)
            {
                throw new WireException($"field \"loaded\" has {loaded.Length} entries for {cells.Length} cells");
            }
        }

        bool? hits = a.TryGetProperty("hits_interior_cell", out var h) && h.ValueKind != JsonValueKind.Null ? ReadBool(a, "hits_interior_cell") : null;
        return new AcPhys.Contract.FindCellResult(cells, ReadOptionalCell(a, "containing")) { Loaded = loaded, HitsInteriorCell = hits };
    }

    /// <summary>
    /// Writes the position's own point as <c>"origin": {x,y,z}</c> when the sphere list is empty and the point is not
    /// (0, 0, 0): the only case retail reads it (facts §3.3 step 3). Absent means (0, 0, 0), so protocol v1 requests
    /// without it keep their meaning.
    /// </summary>
    /// <param name="w">The writer.</param>
    /// <param name="origin">The position's point in its cell's block frame.</param>
    /// <param name="spheres">The spheres of the same request.</param>
    public static void WriteOrigin(Utf8JsonWriter w, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres)
    {
        if (spheres.Count != 0 || origin == System.Numerics.Vector3.Zero)
        {
            return;
        }

        w.WriteStartObject("origin");
        WriteFloat(w, "x", origin.X);
        WriteFloat(w, "y", origin.Y);
        WriteFloat(w, "z", origin.Z);
        w.WriteEndObject();
    }

    /// <summary>Reads the optional <c>"origin": {x,y,z}</c> of a request ((0, 0, 0) when absent or null).</summary>
    /// <param name="request">The request object.</param>
    /// <returns>The point.</returns>
    public static System.Numerics.Vector3 ReadOrigin(JsonElement request)
    {
        if (!request.TryGetProperty("origin", out var o) || o.ValueKind == JsonValueKind.Null)
        {
            return System.Numerics.Vector3.Zero;
        }

        if (o.ValueKind != JsonValueKind.Object)
        {
            throw new WireException("field \"origin\" must be an object {x, y, z}");
        }

        return new System.Numerics.Vector3(FloatValue(Field(o, "x"), "origin.x"), FloatValue(Field(o, "y"), "origin.y"), o.TryGetProperty("z", out var z) ? FloatValue(z, "origin.z") : 0f);
    }

    /// <summary>Writes spheres as <c>[{x,y,z,r}]</c>.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name.</param>
    /// <param name="spheres">The spheres.</param>
    public static void WriteSpheres(Utf8JsonWriter w, string name, IReadOnlyList<Sphere> spheres)
    {
        w.WriteStartArray(name);
        for (int i = 0; i < spheres.Count; i++)
        {
            var s = spheres[i];
            w.WriteStartObject();
            WriteFloat(w, "x"u8, s.Center.X);
            WriteFloat(w, "y"u8, s.Center.Y);
            WriteFloat(w, "z"u8, s.Center.Z);
            WriteFloat(w, "r"u8, s.Radius);
            w.WriteEndObject();
        }

        w.WriteEndArray();
    }

    /// <summary>Writes a vector as <c>{x,y,z}</c>.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name.</param>
    /// <param name="v">The vector.</param>
    public static void WriteVector(Utf8JsonWriter w, string name, Vector3 v)
    {
        w.WriteStartObject(name);
        WriteFloat(w, "x"u8, v.X);
        WriteFloat(w, "y"u8, v.Y);
        WriteFloat(w, "z"u8, v.Z);
        w.WriteEndObject();
    }

    /// <summary>Gets a required property.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The value.</returns>
    /// <exception cref="WireException">The property is missing.</exception>
    public static JsonElement Field(JsonElement obj, string name) =>
        obj.ValueKind == JsonValueKind.Object && obj.TryGetProperty(name, out var v) ? v : throw new WireException($"missing field \"{name}\"");

    /// <summary>Reads a cell id field.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The id.</returns>
    public static CellId ReadCell(JsonElement obj, string name) => CellValue(Field(obj, name), name);

    /// <summary>Reads a cell id field that may be null or absent (<see cref="CellId.None"/> then).</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The id.</returns>
    public static CellId ReadOptionalCell(JsonElement obj, string name) =>
        obj.TryGetProperty(name, out var v) && v.ValueKind != JsonValueKind.Null ? CellValue(v, name) : CellId.None;

    /// <summary>Reads a list of cell ids.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The ids.</returns>
    public static CellId[] ReadCells(JsonElement obj, string name)
    {
        var array = Field(obj, name);
        if (array.ValueKind != JsonValueKind.Array)
        {
            throw new WireException($"field \"{name}\" must be an array of cell ids");
        }

        return array.EnumerateArray().Select(e => CellValue(e, name + "[]")).ToArray();
    }

    /// <summary>Reads a float32 field (a JSON number, or "NaN" / "Infinity" / "-Infinity").</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The value.</returns>
    public static float ReadFloat(JsonElement obj, string name) => FloatValue(Field(obj, name), name);

    /// <summary>Reads an integer field.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The value.</returns>
    public static int ReadInt(JsonElement obj, string name)
    {
        var v = Field(obj, name);
        return v.ValueKind == JsonValueKind.Number && v.TryGetInt32(out int i) ? i : throw new WireException($"field \"{name}\" must be a 32-bit integer, got {Show(v)}");
    }

    /// <summary>Reads a boolean field.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The value.</returns>
    public static bool ReadBool(JsonElement obj, string name)
    {
        var v = Field(obj, name);
        return v.ValueKind switch
        {
            JsonValueKind.True => true,
            JsonValueKind.False => false,
            _ => throw new WireException($"field \"{name}\" must be true or false, got {Show(v)}"),
        };
    }

    /// <summary>Reads a string field.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The value.</returns>
    public static string ReadString(JsonElement obj, string name)
    {
        var v = Field(obj, name);
        return v.ValueKind == JsonValueKind.String ? v.GetString()! : throw new WireException($"field \"{name}\" must be a string, got {Show(v)}");
    }

    /// <summary>Reads spheres <c>[{x,y,z,r}]</c> by the shared rules (<see cref="AcPhys.Formats.Values.SphereList"/>: empty allowed, at most 10,000; <see cref="AcPhys.Formats.Values.SphereRadius"/>), as corpus files read a walk's body.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The spheres.</returns>
    public static Sphere[] ReadSpheres(JsonElement obj, string name)
    {
        var array = Field(obj, name);
        if (array.ValueKind != JsonValueKind.Array)
        {
            throw new WireException($"field \"{name}\" must be an array of {{x,y,z,r}}");
        }

        Refuse(AcPhys.Formats.Values.SphereList.Problem(array.GetArrayLength(), min: 0), name);
        var spheres = new Sphere[array.GetArrayLength()];
        int i = 0;
        foreach (var s in array.EnumerateArray())
        {
            // The item's path is spelt only for a message (issue 26).
            if (s.ValueKind != JsonValueKind.Object)
            {
                throw new WireException($"field \"{name}[{i}]\" must be an object {{x,y,z,r}}, got {Show(s)}");
            }

            float r = FloatAt(s, "r", name, i);
            if (AcPhys.Formats.Values.SphereRadius.Problem(r) is { } bad)
            {
                Refuse(bad, $"{name}[{i}].r");
            }

            spheres[i] = new Sphere(new Vector3(FloatAt(s, "x", name, i), FloatAt(s, "y", name, i), FloatAt(s, "z", name, i)), r);
            i++;
        }

        return spheres;
    }

    /// <summary>Reads a sphere radius field by the shared rule (<see cref="AcPhys.Formats.Values.SphereRadius"/>: finite, ≥ 0).</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The radius.</returns>
    public static float ReadRadius(JsonElement obj, string name)
    {
        float r = ReadFloat(obj, name);
        Refuse(AcPhys.Formats.Values.SphereRadius.Problem(r), name);
        return r;
    }

    /// <summary>Reads a vector <c>{x,y,z}</c>.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <returns>The vector.</returns>
    public static Vector3 ReadVector(JsonElement obj, string name)
    {
        var v = Field(obj, name);
        return new Vector3(ReadFloat(v, "x"), ReadFloat(v, "y"), ReadFloat(v, "z"));
    }

    private static CellId CellValue(JsonElement v, string name) =>
        v.ValueKind == JsonValueKind.String && CellIdText.TryParse(v.GetString(), out var id)
            ? id
            : throw new WireException($"field \"{name}\" must be a cell id string \"0xAABBCCCC\" (8 hex digits), got {Show(v)}");

    /// <summary>Reads a float field that is there and well-formed, with no message built; false sends the caller to its checked read for the words.</summary>
    /// <param name="obj">The object.</param>
    /// <param name="name">The property name.</param>
    /// <param name="value">The value.</param>
    /// <returns>True when read.</returns>
    internal static bool TryReadFloat(JsonElement obj, string name, out float value)
    {
        value = 0;
        return obj.TryGetProperty(name, out var v) && AcPhys.Formats.Values.Float32Json.TryRead(v, nonFiniteNames: true, out value, out _);
    }

    // A float field of list[index]: read at once when it is there and well-formed; otherwise read again as before, for the message.
    private static float FloatAt(JsonElement item, string field, string list, int index) =>
        TryReadFloat(item, field, out float f) ? f : FloatValue(Field(item, field), $"{list}[{index}].{field}");

    private static float FloatValue(JsonElement v, string name) =>
        AcPhys.Formats.Values.Float32Json.TryRead(v, nonFiniteNames: true, out float f, out string? problem) ? f : throw new WireException($"field \"{name}\": {problem}");

    private static void Refuse(string? problem, string name)
    {
        if (problem is not null)
        {
            throw new WireException($"field \"{name}\": {problem}");
        }
    }

    /// <summary>The UTF-8 bytes of a cell id's text, quotes not included.</summary>
    internal const int CellTextBytes = 10;

    /// <summary>Writes <see cref="CellIdText.Format"/>'s text ("0x" and eight upper-case hex digits) as UTF-8, without a string per id (issue 26).</summary>
    /// <param name="id">The id.</param>
    /// <param name="text">At least <see cref="CellTextBytes"/> bytes.</param>
    /// <returns>The text, in <paramref name="text"/>.</returns>
    internal static ReadOnlySpan<byte> CellText(CellId id, Span<byte> text)
    {
        text[0] = (byte)'0';
        text[1] = (byte)'x';
        bool ok = id.Value.TryFormat(text[2..], out int written, "X8", System.Globalization.CultureInfo.InvariantCulture);
        System.Diagnostics.Debug.Assert(ok && written == 8, "a uint is eight hex digits");
        return text[..CellTextBytes];
    }
}
