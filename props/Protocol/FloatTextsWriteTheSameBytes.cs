using AcPhys.Props.Support;
using AcPhys.Protocol.Messages;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Protocol;

/// <summary>
/// PROTOCOL-FLOAT-TEXT: a float32 written through the per-thread table of texts (<see cref="FloatTexts"/>, a parts
/// request's box, radius and rotation, issue 41) gives exactly the bytes of writing it anew
/// (<see cref="Wire.WriteFloat(System.Text.Json.Utf8JsonWriter, ReadOnlySpan{byte}, float)"/>): the first time, when it
/// is kept, and after other values that share its slot replaced it.
/// </summary>
public sealed class FloatTextsWriteTheSameBytes
{
    // Any bit pattern, the special values, and a few walk-like values drawn again and again (hits).
    private static readonly Gen<float> Floats = Gen.OneOf(
        Gen.Choose(int.MinValue, int.MaxValue).Select(BitConverter.Int32BitsToSingle),
        Gen.Elements(0f, -0f, float.Epsilon, -float.Epsilon, float.MaxValue, float.MinValue, float.PositiveInfinity, float.NegativeInfinity, float.NaN, 1e-45f, 191.99998f, 192f),
        Gen.Choose(1, 64).Select(i => 0.4f * (i / 64f)),
        Gen.Choose(-64, 64).Select(i => -0.4f * (i / 64f)));

    [CiProperty(MaxTest = 2000, DisplayName = "PROTOCOL-FLOAT-TEXT: a list of float32 fields written through the table of texts is byte for byte the list written anew")]
    public Property SameBytes() =>
        Prop.ForAll(Gen.ArrayOf(Floats).Select(a => a.Take(64).ToArray()).ToArbitrary(), values =>
        {
            // Each list twice over: the second pass meets every value kept (or replaced by a later one in its slot).
            byte[] kept = Wire.LineUtf8(w =>
            {
                for (int pass = 0; pass < 2; pass++)
                {
                    foreach (float v in values)
                    {
                        FloatTexts.Write(w, "v"u8, v);
                        FloatTexts.WriteVector(w, "p"u8, new System.Numerics.Vector3(v, -v, v));
                    }
                }
            });
            byte[] anew = Wire.LineUtf8(w =>
            {
                for (int pass = 0; pass < 2; pass++)
                {
                    foreach (float v in values)
                    {
                        Wire.WriteFloat(w, "v"u8, v);
                        Wire.WriteVector(w, "p", new System.Numerics.Vector3(v, -v, v));
                    }
                }
            });
            return kept.AsSpan().SequenceEqual(anew).Label(System.Text.Encoding.UTF8.GetString(kept) + " vs " + System.Text.Encoding.UTF8.GetString(anew))
                .Classify(values.Length == 0, "empty");
        });
}
