using System.Buffers.Binary;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Turns bytes into a <see cref="LandCase"/> and back, so that a fuzzer input and a stored case are the same thing.
/// Decoding is total: any byte string (empty included) decodes, never throws.
/// </summary>
/// <remarks>
/// <para>Layout (missing bytes read as zero): <c>mode:u8 cell:u32 x:4 y:4 lx:i16 ly:i16</c>, little-endian, 17 bytes.</para>
/// <para>The mode byte biases the fuzzer towards the classes that matter. Bits 0–1 select how x's four bytes read,
/// bits 2–3 the same for y: 0 raw float32 bits; 1 a 24 m line <c>24·k</c> (k = i16) moved by a signed ULP count
/// (i8, clamped to ±8); 2 a small value <c>i32·1e-9</c> m (the EPS snap band and its edges); 3 a special value
/// from <see cref="Specials"/>. Bit 6 forces the cell's low word into the land range 1..64.</para>
/// </remarks>
public static class LandCaseCodec
{
    /// <summary>Length of one encoded case.</summary>
    public const int Length = 17;

    /// <summary>Special float32 values reachable with coordinate encoding 3.</summary>
    public static readonly float[] Specials =
    [
        float.NaN, float.PositiveInfinity, float.NegativeInfinity, -0f, 0f, float.Epsilon, -float.Epsilon,
        float.MaxValue, float.MinValue, 1e6f, -1e6f, LandDefs.Epsilon, -LandDefs.Epsilon, 192f, -192f, 24f,
        1.17549435e-38f, -1.17549421e-38f,
    ];

    /// <summary>Decodes bytes into a case.</summary>
    /// <param name="data">Any bytes.</param>
    /// <returns>The case.</returns>
    public static LandCase Decode(ReadOnlySpan<byte> data)
    {
        Span<byte> buffer = stackalloc byte[Length];
        buffer.Clear();
        data[..Math.Min(data.Length, Length)].CopyTo(buffer);

        byte mode = buffer[0];
        uint cell = BinaryPrimitives.ReadUInt32LittleEndian(buffer[1..]);
        if ((mode & 0x40) != 0)
        {
            cell = (cell & LandDefs.BlockMask) | (uint)(1 + ((cell & 0xFFFF) % 64));
        }

        float x = DecodeCoordinate(mode & 3, buffer.Slice(5, 4));
        float y = DecodeCoordinate((mode >> 2) & 3, buffer.Slice(9, 4));
        int lx = BinaryPrimitives.ReadInt16LittleEndian(buffer[13..]);
        int ly = BinaryPrimitives.ReadInt16LittleEndian(buffer[15..]);
        return new LandCase(new CellId(cell), x, y, new Lcoord(lx, ly));
    }

    /// <summary>Encodes a case with raw float bits (mode 0), the form stored as fuzzer seeds.</summary>
    /// <param name="landCase">The case; lcoords are stored as 16-bit values (clamped).</param>
    /// <returns>17 bytes that decode to the same case (lcoords clamped to the i16 range).</returns>
    public static byte[] Encode(LandCase landCase)
    {
        var bytes = new byte[Length];
        BinaryPrimitives.WriteUInt32LittleEndian(bytes.AsSpan(1), landCase.Cell.Value);
        BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(5), landCase.X);
        BinaryPrimitives.WriteSingleLittleEndian(bytes.AsSpan(9), landCase.Y);
        BinaryPrimitives.WriteInt16LittleEndian(bytes.AsSpan(13), ClampToInt16(landCase.Lcoord.X));
        BinaryPrimitives.WriteInt16LittleEndian(bytes.AsSpan(15), ClampToInt16(landCase.Lcoord.Y));
        return bytes;
    }

    private static float DecodeCoordinate(int encoding, ReadOnlySpan<byte> field)
    {
        switch (encoding)
        {
            case 1:
                {
                    int line = BinaryPrimitives.ReadInt16LittleEndian(field);
                    return Ulps.Step(line * LandDefs.CellLength, Math.Clamp((int)(sbyte)field[2], -8, 8));
                }

            case 2:
                return BinaryPrimitives.ReadInt32LittleEndian(field) * 1e-9f;
            case 3:
                return Specials[field[0] % Specials.Length];
            default:
                return BinaryPrimitives.ReadSingleLittleEndian(field);
        }
    }

    private static short ClampToInt16(int v) => (short)Math.Clamp(v, short.MinValue, short.MaxValue);
}
