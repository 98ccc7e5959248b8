using System.Text.Json;
using AcPhys.Core;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Protocol;

namespace AcPhys.E2E;

/// <summary>Protocol v1 encoding: every float32 and every cell id crosses the wire unchanged; the server answers malformed requests with an error.</summary>
public sealed class WireTests
{
    [Fact]
    public void EveryFloat32RoundTripsBitForBit()
    {
        // Special values first, then 200,000 random bit patterns (fixed seed): NaN payloads aside, the bits come back.
        var random = new Random(20261122);
        var specials = new[] { 0f, -0f, float.Epsilon, -float.Epsilon, float.MaxValue, float.MinValue, float.NaN, float.PositiveInfinity, float.NegativeInfinity, 191.99998f, -0.0001f, 1e-39f };
        foreach (float v in specials.Concat(Enumerable.Range(0, 200_000).Select(_ => BitConverter.Int32BitsToSingle(random.Next(int.MinValue, int.MaxValue)))))
        {
            string line = Wire.Line(w => Wire.WriteFloat(w, "x", v));
            using var doc = Wire.Parse(line);
            float back = Wire.ReadFloat(doc.RootElement, "x");
            if (float.IsNaN(v))
            {
                Assert.True(float.IsNaN(back), line);
            }
            else
            {
                Assert.True(BitConverter.SingleToInt32Bits(v) == BitConverter.SingleToInt32Bits(back), $"{v:R} came back as {back:R} via {line}");
            }
        }
    }

    [Fact]
    public void CellIdsAreEightHexDigitStringsBothWays()
    {
        Assert.Equal("{\"cell\":\"0xA9B40001\"}", Wire.Line(w => Wire.WriteCell(w, "cell", new CellId(0xA9B40001))));
        using var ok = Wire.Parse("{\"cell\":\"0xa9b4FFFF\"}");
        Assert.Equal(0xA9B4FFFFu, Wire.ReadCell(ok.RootElement, "cell").Value);
        foreach (string bad in new[] { "{\"cell\":\"0xA9B4001\"}", "{\"cell\":2847145985}", "{\"cell\":\"A9B40001\"}", "{\"cell\":\"0xA9B4000G\"}", "{}" })
        {
            using var doc = Wire.Parse(bad);
            Assert.Throws<WireException>(() => Wire.ReadCell(doc.RootElement, "cell"));
        }
    }

    [Fact]
    public void ServerAnswersEveryOpAndRefusesWhatItCannotServe()
    {
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        Assert.Equal("{\"ok\":true,\"x\":1352,\"y\":1440}", server.Answer("{\"op\":\"blockid_to_lcoord\",\"cell\":\"0xA9B40001\"}"));
        Assert.Equal("{\"cell\":\"0x00000000\"}", server.Answer("{\"op\":\"lcoord_to_gid\",\"x\":2040,\"y\":0}"));
        Assert.Equal("{\"ok\":true,\"cell\":\"0xA8B40039\",\"x\":191.5,\"y\":0}", server.Answer("{\"op\":\"adjust_to_outside\",\"cell\":\"0xA9B40001\",\"x\":-0.5,\"y\":-0.0001}"));
        Assert.Equal("{\"ok\":false,\"x\":0,\"y\":0}", server.Answer("{\"op\":\"get_outside_lcoord\",\"cell\":\"0xA9B40001\",\"x\":\"NaN\",\"y\":0}"));
        Assert.Equal("{\"error\":\"scenes not supported yet\"}", server.Answer("{\"op\":\"find_cell\",\"scene\":{},\"cell\":\"0xA9B40001\",\"spheres\":[],\"current\":null}"));
        Assert.StartsWith("{\"error\":\"unknown op", server.Answer("{\"op\":\"teleport\"}"), StringComparison.Ordinal);
        Assert.StartsWith("{\"error\":\"malformed request: not JSON", server.Answer("hello"), StringComparison.Ordinal);
        using var hello = JsonDocument.Parse(server.Answer("{\"op\":\"hello\",\"protocol\":1}"));
        Assert.Equal(9, hello.RootElement.GetProperty("ops").GetArrayLength());
        Assert.StartsWith("{\"error\":\"protocol 2 not supported", server.Answer("{\"op\":\"hello\",\"protocol\":2}"), StringComparison.Ordinal);
    }
}
