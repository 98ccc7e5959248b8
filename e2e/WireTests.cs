using System.Numerics;
using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Scenes;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Server;
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
        Assert.Equal(18, hello.RootElement.GetProperty("ops").GetArrayLength()); // protocol v1 with find_cell_scene, find_cell_transition, find_cell_parts_scene, find_cell_parts_transition, load_scene, dat_records, find_cell_walk, find_cell_parts_walk and pipeline
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
    [Fact]
    public void FindCellAnswersCarryLoadHintFlagsAndHitsInteriorCellAndTransitionQueriesSkipTheFilter()
    {
        // Protocol v1, compatible extension: "loaded" parallel to "cells", "hits_interior_cell", and "load_cells": true
        // for a movement transition (no visibility filter), served by an implementation announcing find_cell_transition.
        var plan = new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 1, 6f, 6f, 0, false, false);
        var scene = SceneKit.Cottage(plan);
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        var room = plan.RoomId(0);
        var spheres = new[] { new Sphere(plan.ToBlock(new Vector3(3, 0.2f, 0.6f)), 0.5f) };
        string Request(bool transition) => Wire.Line(w =>
        {
            w.WriteString("op", "find_cell");
            w.WritePropertyName("scene");
            w.WriteRawValue(SceneJson.WriteCompact(scene));
            Wire.WriteCell(w, "cell", room);
            Wire.WriteSpheres(w, "spheres", spheres);
            w.WriteNull("current");
            if (transition)
            {
                w.WriteBoolean("load_cells", true);
            }
        });
        foreach (bool transition in new[] { false, true })
        {
            using var answer = Wire.Parse(server.Answer(Request(transition)));
            var got = Wire.ReadFindCell(answer.RootElement);
            var expected = ReferenceAdapter.Instance.FindCell(scene, room, spheres, CellId.None, transition);
            Assert.Equal(expected.Cells, got.Cells);
            Assert.Equal(expected.Loaded, got.Loaded);
            Assert.True(got.HitsInteriorCell);
            Assert.Equal(transition, got.Cells.Any(c => c.IsLand)); // the exit's land cells survive only without the filter
        }

        Assert.Contains("\"loaded\":[true", server.Answer("{\"op\":\"find_cell\",\"scene\":null,\"cell\":\"0xA9B40001\",\"spheres\":[{\"x\":1,\"y\":1,\"z\":0,\"r\":0.5}],\"current\":null}"), StringComparison.Ordinal);
    }

    [Fact]
    public void MalformedFlagsAreProtocolErrorsAndAbsentFlagsStayUnreported()
    {
        using var mismatch = Wire.Parse("{\"cells\":[\"0xA9B40001\"],\"containing\":null,\"loaded\":[true,false]}");
        Assert.Contains("has 2 entries for 1 cells", Assert.Throws<WireException>(() => Wire.ReadFindCell(mismatch.RootElement)).Message, StringComparison.Ordinal);
        using var notBool = Wire.Parse("{\"cells\":[\"0xA9B40001\"],\"containing\":null,\"loaded\":[1]}");
        Assert.Throws<WireException>(() => Wire.ReadFindCell(notBool.RootElement));
        using var plain = Wire.Parse("{\"cells\":[\"0xA9B40001\"],\"containing\":\"0xA9B40001\"}");
        var r = Wire.ReadFindCell(plain.RootElement);
        Assert.Null(r.Loaded);
        Assert.Null(r.HitsInteriorCell);
    }

    [Fact]
    public void HelloDeclaresTheDocumentedDeviationsAndUnknownNamesAreRefused()
    {
        var ace = new ReferenceAdapter(PickPolicy.Retail, outdoor: OutdoorFidelity.Ace) { Indoor = IndoorFidelity.Ace };
        using var hello = JsonDocument.Parse(new ProtocolServer(ace).Answer("{\"op\":\"hello\",\"protocol\":1}"));
        var names = hello.RootElement.GetProperty("fidelity").EnumerateArray().Select(e => e.GetString()!).ToArray();
        Assert.True(FidelityNames.TryParse(names, out var indoor, out var outdoor, out _));
        Assert.Equal(IndoorFidelity.Ace, indoor);
        Assert.Equal(OutdoorFidelity.Ace, outdoor);
        using var retail = JsonDocument.Parse(new ProtocolServer(ReferenceAdapter.Instance).Answer("{\"op\":\"hello\",\"protocol\":1}"));
        Assert.False(retail.RootElement.TryGetProperty("fidelity", out _)); // retail says nothing
        Assert.False(FidelityNames.TryParse(["ace", "teleport-fix"], out _, out _, out var bad));
        Assert.Equal("teleport-fix", bad);
        Assert.True(FidelityNames.TryParse(["double"], out _, out var d, out _));
        Assert.Equal(OutdoorPrecision.Double, d.Precision);
    }
    [Fact]
    public void ALoadedSceneIsNamedByItsIdUntilUnloaded()
    {
        var plan = new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0.3f, 2, 6f, 6f, 0, true, false);
        var scene = SceneKit.Cottage(plan);
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        using var hello = JsonDocument.Parse(server.Answer("{\"op\":\"hello\",\"protocol\":1}"));
        Assert.Contains(hello.RootElement.GetProperty("ops").EnumerateArray(), e => e.GetString() == "load_scene");
        using var loaded = Wire.Parse(server.Answer(Wire.Line(w =>
        {
            w.WriteString("op", "load_scene");
            w.WritePropertyName("scene");
            w.WriteRawValue(SceneJson.WriteCompact(scene));
        })));
        string id = Wire.ReadString(loaded.RootElement, "scene_id");
        var spheres = new[] { new Sphere(plan.ToBlock(new Vector3(3, 3, 0.6f)), 0.5f) };
        string ById() => server.Answer(Wire.Line(w =>
        {
            w.WriteString("op", "find_cell");
            w.WriteString("scene_id", id);
            Wire.WriteCell(w, "cell", plan.RoomId(0));
            Wire.WriteSpheres(w, "spheres", spheres);
            w.WriteNull("current");
        }));
        using (var answer = Wire.Parse(ById()))
        {
            var expected = ReferenceAdapter.Instance.FindCell(scene, plan.RoomId(0), spheres, CellId.None);
            Assert.Equal(expected.Cells, Wire.ReadFindCell(answer.RootElement).Cells);
        }

        Assert.Equal("{\"ok\":true}", server.Answer($"{{\"op\":\"unload_scene\",\"scene_id\":\"{id}\"}}"));
        Assert.StartsWith("{\"error\":\"unknown scene_id", ById(), StringComparison.Ordinal);
        Assert.StartsWith("{\"error\":\"unknown scene_id", server.Answer($"{{\"op\":\"unload_scene\",\"scene_id\":\"{id}\"}}"), StringComparison.Ordinal);
        var older = new ProtocolServer(ReferenceAdapter.Instance) { LoadScenes = false };
        using var plain = JsonDocument.Parse(older.Answer("{\"op\":\"hello\",\"protocol\":1}"));
        Assert.DoesNotContain(plain.RootElement.GetProperty("ops").EnumerateArray(), e => e.GetString() == "load_scene");
    }

    [Fact]
    public void AClientHoldsAtMostTheServersLimitOfScenes()
    {
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        string Load(int i) => server.Answer(Wire.Line(w =>
        {
            w.WriteString("op", "load_scene");
            w.WritePropertyName("scene");
            w.WriteRawValue(SceneJson.WriteCompact(SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 20 + i, (0xB4 * 192.0) + 50, 0, 1, 6f, 6f, 0, false, false))));
        }));
        for (int i = 0; i < ProtocolServer.MaxLoadedScenes; i++)
        {
            Assert.StartsWith("{\"scene_id\":", Load(i), StringComparison.Ordinal);
        }

        Assert.StartsWith("{\"error\":\"64 scenes already loaded", Load(99), StringComparison.Ordinal);
    }

    [Fact(DisplayName = "A request line that is JSON but not an object, or names a huge unknown op, gets a short clear error (issue #19)")]
    public void NonObjectsAndHugeOpNamesAreShortErrors()
    {
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        Assert.Equal("{\"error\":\"malformed request: expected a JSON object, got Array\"}", server.Answer("[1,2,3]"));
        Assert.Equal("{\"error\":\"malformed request: expected a JSON object, got Null\"}", server.Answer("null"));
        string huge = server.Answer($"{{\"op\":\"{new string('x', 1 << 20)}\"}}");
        Assert.StartsWith("{\"error\":\"unknown op", huge, StringComparison.Ordinal);
        Assert.True(huge.Length < 200, $"the error echoes {huge.Length} characters");
    }

    [Fact]
    public void DuplicateKeysInARequestAreAnErrorNamingThePath()
    {
        // Once the last "op" won silently.
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        Assert.Equal("{\"error\":\"malformed request: $.op: duplicate key \\\"op\\\" (each key once per object)\"}", server.Answer("{\"op\":\"hello\",\"op\":\"frob\"}"));
    }
}
