using System.Numerics;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Protocol;
using AcPhys.Spec.Scenes;

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
        Assert.StartsWith("{\"error\":\"malformed request: invalid scene: find_cell: $.scene", server.Answer("{\"op\":\"find_cell\",\"scene\":{},\"cell\":\"0xA9B40001\",\"spheres\":[],\"current\":null}"), StringComparison.Ordinal);
        Assert.StartsWith("{\"error\":\"unknown op", server.Answer("{\"op\":\"teleport\"}"), StringComparison.Ordinal);
        Assert.StartsWith("{\"error\":\"malformed request: not JSON", server.Answer("hello"), StringComparison.Ordinal);
        using var hello = JsonDocument.Parse(server.Answer("{\"op\":\"hello\",\"protocol\":1}"));
        Assert.Equal(11, hello.RootElement.GetProperty("ops").GetArrayLength());
        Assert.StartsWith("{\"error\":\"protocol 2 not supported", server.Answer("{\"op\":\"hello\",\"protocol\":2}"), StringComparison.Ordinal);
    }

    [Fact]
    public void SceneQueriesOverTheWireAnswerLikeTheReferenceInProcess()
    {
        // A two-room cottage in 0xA9B4 at (50, 50): the scene travels as compact JSON in find_cell and the server's
        // answer, read back, equals the in-process reference answer for points outside, in each room and at a door.
        var plan = new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0.3f, 2, 6f, 6f, 0b101, true, true);
        var scene = SceneKit.Cottage(plan);
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        var owner = new CellId(0xA9B40013);
        var points = new[] { new Vector3(53, 49, 0.5f), new Vector3(53, 51, 0.5f), plan.ToBlock(new Vector3(3, 3, 0.5f)), plan.ToBlock(new Vector3(9, 3, 0.5f)), plan.ToBlock(new Vector3(3, 0.1f, 0.5f)) };
        int indoors = 0;
        foreach (var p in points)
        {
            var spheres = new[] { new Sphere(p, 0.5f) };
            var expected = ReferenceAdapter.Instance.FindCell(scene, owner, spheres, CellId.None);
            string request = Wire.Line(w =>
            {
                w.WriteString("op", "find_cell");
                w.WritePropertyName("scene");
                w.WriteRawValue(SceneJson.WriteCompact(scene));
                Wire.WriteCell(w, "cell", owner);
                Wire.WriteSpheres(w, "spheres", spheres);
                w.WriteNull("current");
            });
            Assert.DoesNotContain('\n', request);
            using var answer = Wire.Parse(server.Answer(request));
            Assert.Equal(expected.Cells, Wire.ReadCells(answer.RootElement, "cells"));
            Assert.Equal(expected.Containing, Wire.ReadOptionalCell(answer.RootElement, "containing"));
            indoors += expected.Containing.IsLand ? 0 : 1;
        }

        Assert.True(indoors >= 2, $"only {indoors} of the points were indoors; the test would not see a scene being ignored");
    }
}
