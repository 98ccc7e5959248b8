using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Turns bytes into a <see cref="PartsCase"/>, so that a fuzzer input is a parts query. Decoding is total: any byte
/// string (empty included) decodes to a bounded, valid case of 1–4 parts, never throws.
/// </summary>
/// <remarks>
/// <para>Layout (missing bytes read as zero, extra bytes ignored): a header <c>count:u8 blockX:u8 blockY:u8</c>, then
/// four 12-byte part records, of which the first <c>1 + (count &amp; 3)</c> are used; the first part is the anchor.</para>
/// <para>A part record is <c>flags x:2 y:2 rot:4 hx hy hz</c>. Flags: bit 0 Always2D; bits 1–2 the rotation
/// (0 and 3 identity, 1 a yaw of <c>rot[0]·360/256</c>°, 2 the normalised quaternion of the four signed bytes
/// <c>(x, y, z, w)</c>, identity when all are zero); bit 3 (x) and bit 4 (y) choose a coordinate's form: clear, the
/// u16 times 3/1024 m (0 to 192 m across the block); set, a cell or block line <c>24·(b0 mod 9)</c> moved by the
/// signed second byte in 1/32 m (±4 m: the block lines 0 and 192 and their corners); bits 5–7 the part's block as a
/// step from the header's block (<see cref="BlockSteps"/>, clamped to 0..255, so a part may sit in a neighbouring
/// block's frame). Half extents are <c>0.05 + 14.95·(b/255)²</c> m, the Always2D radius is the x half extent, z is
/// 0.5 m, and the cell's low word is the land cell of the origin (clamped into the block).</para>
/// </remarks>
public static class PartsCodec
{
    /// <summary>Most parts one input decodes to.</summary>
    public const int MaxParts = 4;

    /// <summary>Length of the header.</summary>
    public const int HeaderLength = 3;

    /// <summary>Length of one part record.</summary>
    public const int PartLength = 12;

    /// <summary>Length of the longest meaningful input.</summary>
    public const int Length = HeaderLength + (MaxParts * PartLength);

    /// <summary>The block steps selected by flag bits 5–7: the header's block and its neighbours.</summary>
    public static readonly (int X, int Y)[] BlockSteps = [(0, 0), (1, 0), (0, 1), (1, 1), (-1, 0), (0, -1), (-1, -1), (1, -1)];

    /// <summary>Decodes bytes into a parts query.</summary>
    /// <param name="data">Any bytes.</param>
    /// <returns>The query (1–4 parts, finite values).</returns>
    public static PartsCase Decode(ReadOnlySpan<byte> data)
    {
        Span<byte> buffer = stackalloc byte[Length];
        buffer.Clear();
        data[..Math.Min(data.Length, Length)].CopyTo(buffer);

        int count = 1 + (buffer[0] & 3);
        var parts = new Part[count];
        for (int i = 0; i < count; i++)
        {
            parts[i] = DecodePart(buffer[1], buffer[2], buffer.Slice(HeaderLength + (i * PartLength), PartLength));
        }

        return new PartsCase(parts);
    }

    private static Part DecodePart(byte blockX, byte blockY, ReadOnlySpan<byte> p)
    {
        byte flags = p[0];
        var step = BlockSteps[flags >> 5];
        float x = Coordinate((flags & 8) != 0, p[1], p[2]);
        float y = Coordinate((flags & 16) != 0, p[3], p[4]);
        int cx = Math.Clamp((int)MathF.Floor(x / LandDefs.CellLength), 0, 7);
        int cy = Math.Clamp((int)MathF.Floor(y / LandDefs.CellLength), 0, 7);
        var cell = new CellId((byte)Math.Clamp(blockX + step.X, 0, 255), (byte)Math.Clamp(blockY + step.Y, 0, 255), (ushort)(1 + (8 * cx) + cy));
        float hx = Half(p[9]), hy = Half(p[10]), hz = Half(p[11]);
        return new Part(
            cell,
            new Frame(new Vector3(x, y, 0.5f), Rotation((flags >> 1) & 3, p.Slice(5, 4))),
            new Box(new Vector3(-hx, -hy, -hz), new Vector3(hx, hy, hz)),
            hx,
            (flags & 1) != 0);
    }

    private static float Coordinate(bool line, byte a, byte b) =>
        line ? (LandDefs.CellLength * (a % 9)) + ((sbyte)b / 32f) : (a | (b << 8)) * (3f / 1024f);

    private static Quaternion Rotation(int kind, ReadOnlySpan<byte> r)
    {
        switch (kind)
        {
            case 1:
                return Quaternion.CreateFromAxisAngle(Vector3.UnitZ, r[0] * (2 * MathF.PI / 256f));
            case 2:
                var q = new Quaternion((sbyte)r[0], (sbyte)r[1], (sbyte)r[2], (sbyte)r[3]);
                return q == default ? Quaternion.Identity : Quaternion.Normalize(q);
            default:
                return Quaternion.Identity;
        }
    }

    private static float Half(byte b) => 0.05f + (14.95f * (b / 255f) * (b / 255f));
}
