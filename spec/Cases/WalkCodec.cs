using System.Buffers.Binary;
using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Turns any bytes into a bounded, valid walk, so that every fuzzer input reaches the physics, never the parser.
/// Total: any byte string (empty included) decodes, never throws; at most 3 spheres and 16 steps.
/// </summary>
/// <remarks>
/// Layout (missing bytes read as zero): <c>cell:u32 x:u16 y:u16 nbody:u8</c>, then per sphere <c>dx:i8 dy:i8 r:u8</c>
/// (offsets in 1/16 m, radius in 1/16 m: 0 to 15.9 m, so 12 and above are reachable), then per step
/// <c>scale:u8 dx:i8 dy:i8</c>, where the scale byte picks per axis one of 2⁻¹⁶ m (a float32 ULP at 192 m),
/// 2⁻⁶ m, 1 m or 24 m. The cell's block bytes are folded into 0x00..0xFE and its low word into 1..64; the start
/// is <c>u16 · 192/65536</c>, inside the block. Every value is exactly representable, so walks are exact.
/// </remarks>
public static class WalkCodec
{
    /// <summary>Most steps a decoded walk has.</summary>
    public const int MaxSteps = 16;

    private static readonly float[] Scales = [1f / 65536f, 1f / 64f, 1f, 24f];

    /// <summary>Decodes bytes into a walk.</summary>
    /// <param name="data">Any bytes.</param>
    /// <returns>The walk.</returns>
    public static Walk Decode(ReadOnlySpan<byte> data)
    {
        var reader = new Reader(data);
        uint raw = reader.U32();
        var cell = new CellId((byte)((raw >> 24) % 255), (byte)(((raw >> 16) & 0xFF) % 255), (ushort)(1 + ((raw & 0xFFFF) % 64)));
        float x = reader.U16() * (192f / 65536f);
        float y = reader.U16() * (192f / 65536f);
        int count = 1 + (reader.U8() % 3);
        var body = new BodySphere[count];
        for (int i = 0; i < count; i++)
        {
            float dx = i == 0 ? 0 : (sbyte)reader.U8() / 16f, dy = i == 0 ? 0 : (sbyte)reader.U8() / 16f;
            body[i] = new BodySphere(new Vector3(dx, dy, 0.5f), reader.U8() / 16f);
        }

        var steps = new List<Vector2>();
        while (reader.Remaining >= 3 && steps.Count < MaxSteps)
        {
            byte scale = reader.U8();
            steps.Add(new Vector2((sbyte)reader.U8() * Scales[scale & 3], (sbyte)reader.U8() * Scales[(scale >> 2) & 3]));
        }

        return new Walk(cell, new Vector3(x, y, 0), body, steps).Normalised();
    }

    private ref struct Reader(ReadOnlySpan<byte> data)
    {
        private readonly ReadOnlySpan<byte> data = data;
        private int position;

        public readonly int Remaining => Math.Max(data.Length - position, 0);

        public byte U8() => position < data.Length ? data[position++] : Skip(1);

        public ushort U16() => Remaining >= 2 ? BinaryPrimitives.ReadUInt16LittleEndian(Take(2)) : (ushort)(U8() | (U8() << 8));

        public uint U32() => Remaining >= 4 ? BinaryPrimitives.ReadUInt32LittleEndian(Take(4)) : (uint)(U16() | (U16() << 16));

        private ReadOnlySpan<byte> Take(int n)
        {
            var slice = data.Slice(position, n);
            position += n;
            return slice;
        }

        private byte Skip(int n)
        {
            position += n;
            return 0;
        }
    }
}
