using System.Buffers.Binary;
using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>Little-endian record writer; <see cref="Align"/> pads from the record's first byte (dat-records.md, ALIGN).</summary>
public sealed class ByteWriter
{
    // A plain array that doubles when full (issue 26: an ArrayBufferWriter's span per value was a third of writing an Environment).
    private byte[] buffer;
    private int written;

    /// <summary>Initializes a new instance.</summary>
    /// <param name="capacity">The bytes to hold before the first growth.</param>
    public ByteWriter(int capacity = 256) => buffer = new byte[Math.Max(16, capacity)];

    /// <summary>Gets the number of bytes written.</summary>
    public int Position => written;

    /// <summary>Returns the bytes.</summary>
    /// <returns>The record.</returns>
    public byte[] ToArray() => buffer.AsSpan(0, written).ToArray();

    /// <summary>Writes a byte.</summary>
    /// <param name="v">The value.</param>
    public void U8(byte v) => Room(1)[0] = v;

    /// <summary>Writes a u16.</summary>
    /// <param name="v">The value.</param>
    public void U16(ushort v) => BinaryPrimitives.WriteUInt16LittleEndian(Room(2), v);

    /// <summary>Writes an i16.</summary>
    /// <param name="v">The value.</param>
    public void I16(short v) => U16(unchecked((ushort)v));

    /// <summary>Writes a u32.</summary>
    /// <param name="v">The value.</param>
    public void U32(uint v) => BinaryPrimitives.WriteUInt32LittleEndian(Room(4), v);

    /// <summary>Writes an i32.</summary>
    /// <param name="v">The value.</param>
    public void I32(int v) => U32(unchecked((uint)v));

    /// <summary>Writes an f32.</summary>
    /// <param name="v">The value.</param>
    public void F32(float v) => U32(BitConverter.SingleToUInt32Bits(v));

    /// <summary>Writes a Vector3.</summary>
    /// <param name="v">The value.</param>
    public void Vec(Vector3 v)
    {
        F32(v.X);
        F32(v.Y);
        F32(v.Z);
    }

    /// <summary>Writes a Frame: origin, then the quaternion W, X, Y, Z (facts §5.8).</summary>
    /// <param name="origin">The origin.</param>
    /// <param name="q">The rotation.</param>
    public void Frame(Vector3 origin, Quaternion q)
    {
        Vec(origin);
        F32(q.W);
        F32(q.X);
        F32(q.Y);
        F32(q.Z);
    }

    /// <summary>Writes a Plane: normal, d.</summary>
    /// <param name="p">The plane.</param>
    public void Plane(CellPlane p)
    {
        Vec(p.Normal);
        F32(p.D);
    }

    /// <summary>Writes a Sphere: centre, radius.</summary>
    /// <param name="s">The sphere.</param>
    public void Sphere(Sphere s)
    {
        Vec(s.Center);
        F32(s.Radius);
    }

    /// <summary>Pads with zeros to a multiple of 4 bytes from the record start.</summary>
    public void Align()
    {
        while (Position % 4 != 0)
        {
            U8(0);
        }
    }

    // The next `bytes` bytes, counted as written.
    private Span<byte> Room(int bytes)
    {
        if (buffer.Length - written < bytes)
        {
            Array.Resize(ref buffer, Math.Max(buffer.Length * 2, written + bytes));
        }

        var room = buffer.AsSpan(written, bytes);
        written += bytes;
        return room;
    }
}
