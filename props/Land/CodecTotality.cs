using AcPhys.Props.Support;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Land;

/// <summary>The fuzzer's byte codec: every byte string decodes, and encoded cases decode to themselves.</summary>
public sealed class CodecTotality
{
    [CiProperty(MaxTest = 3000, DisplayName = "LandCaseCodec: any bytes decode without throwing, empty and oversized included")]
    public Property AnyBytesDecode() =>
        Prop.ForAll(ArbMap.Default.ArbFor<byte[]>(), bytes =>
        {
            _ = LandCaseCodec.Decode(bytes ?? []);
            return true;
        });

    [CiProperty(MaxTest = 3000, DisplayName = "LandCaseCodec: Encode then Decode gives the case back bit for bit (NaN and -0 included)")]
    public Property EncodeDecodeRoundTrips() =>
        Prop.ForAll(LandGens.Cases.Where(c => c.Lcoord.X is >= short.MinValue and <= short.MaxValue && c.Lcoord.Y is >= short.MinValue and <= short.MaxValue).ToArbitrary(), c =>
        {
            var back = LandCaseCodec.Decode(LandCaseCodec.Encode(c));
            return back.Cell == c.Cell && back.Lcoord == c.Lcoord
                && BitConverter.SingleToInt32Bits(back.X) == BitConverter.SingleToInt32Bits(c.X)
                && BitConverter.SingleToInt32Bits(back.Y) == BitConverter.SingleToInt32Bits(c.Y);
        });

    [Fact(DisplayName = "LandCaseCodec: the line encoding reaches exact 24 m lines and their ULP neighbours")]
    public void LineEncodingReachesLines()
    {
        // mode 1 (x by line), line k = 8 (192 m), +3 ULP
        byte[] bytes = [0x01, 1, 0, 0, 0, 8, 0, 3, 0];
        var c = LandCaseCodec.Decode(bytes);
        Assert.Equal(MathF.BitIncrement(MathF.BitIncrement(MathF.BitIncrement(192f))), c.X);
        Assert.Equal(0f, c.Y);
    }
}
