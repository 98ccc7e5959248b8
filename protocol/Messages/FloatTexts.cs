using System.Buffers;
using System.Text.Json;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// The text of float32 values a request writes again and again: a parts query's box corners, radius and rotation are
/// the same at most steps of a walk (issue 41; docs/protocol.md, "Speed": 74 parts queries a walk, the shortest text of
/// each double written anew was a tenth of the served run). Each value's text is made once by
/// <see cref="Wire.WriteFloatValue"/>, kept in a small per-thread table by its bits, and written raw after, so the
/// bytes are the same as writing the value each time (PROTOCOL-FLOAT-TEXT, props).
/// </summary>
internal static class FloatTexts
{
    private const int SlotBits = 10;

    [ThreadStatic]
    private static uint[]? keys;

    [ThreadStatic]
    private static byte[]?[]? texts;

    [ThreadStatic]
    private static ArrayBufferWriter<byte>? scratch;

    [ThreadStatic]
    private static Utf8JsonWriter? scratchWriter;

    /// <summary>Writes a float32 field, as <see cref="Wire.WriteFloat(Utf8JsonWriter, ReadOnlySpan{byte}, float)"/> writes it.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name, UTF-8.</param>
    /// <param name="v">The value.</param>
    public static void Write(Utf8JsonWriter w, ReadOnlySpan<byte> name, float v)
    {
        w.WritePropertyName(name);
        WriteValue(w, v);
    }

    /// <summary>Writes a float32 value, as <see cref="Wire.WriteFloatValue"/> writes it.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="v">The value.</param>
    public static void WriteValue(Utf8JsonWriter w, float v)
    {
        uint bits = BitConverter.SingleToUInt32Bits(v);
        var k = keys ??= new uint[1 << SlotBits];
        var t = texts ??= new byte[1 << SlotBits][];
        int slot = (int)((bits * 2654435769u) >> (32 - SlotBits)); // Fibonacci hashing: nearby bit patterns spread out
        var text = t[slot];
        if (text is null || k[slot] != bits)
        {
            text = t[slot] = TextOf(v);
            k[slot] = bits;
        }

        w.WriteRawValue(text, skipInputValidation: true);
    }

    /// <summary>Writes a vector field <c>{x, y, z}</c>, as <see cref="Wire.WriteVector"/> writes it.</summary>
    /// <param name="w">The writer.</param>
    /// <param name="name">The property name, UTF-8.</param>
    /// <param name="v">The vector.</param>
    public static void WriteVector(Utf8JsonWriter w, ReadOnlySpan<byte> name, System.Numerics.Vector3 v)
    {
        w.WriteStartObject(name);
        Write(w, "x"u8, v.X);
        Write(w, "y"u8, v.Y);
        Write(w, "z"u8, v.Z);
        w.WriteEndObject();
    }

    // The value's text, written alone by the one float writer of the protocol.
    private static byte[] TextOf(float v)
    {
        var buffer = scratch ??= new ArrayBufferWriter<byte>(32);
        buffer.ResetWrittenCount();
        var writer = scratchWriter ??= new Utf8JsonWriter(buffer, Wire.WriterOptions);
        writer.Reset(buffer);
        Wire.WriteFloatValue(writer, v);
        writer.Flush();
        return buffer.WrittenSpan.ToArray();
    }
}
