using System.Numerics;
using System.Text;
using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Scenes;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Server;
using AcPhys.Spec.Scenes;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>serve-request</c> parser target: bytes → up to <see cref="MaxLines"/> request lines → a fresh
/// <see cref="ProtocolServer"/> over the reference core (<see cref="ProtocolServer.AnswerChecked(string)"/>), as
/// <c>acphys serve</c> reads them; a second server is fed each line's bytes
/// (<see cref="ProtocolServer.AnswerChecked(System.ReadOnlyMemory{byte})"/>, how serve parses a valid UTF-8 line) and must
/// answer alike. A bad request must be answered with <c>{"error": ...}</c>; any exception that
/// escapes is a bug (the server would answer "internal error"), and so is an answer that is not one JSON object.
/// Several lines let a campaign reach <c>load_scene</c> followed by <c>find_cell</c> on the loaded scene, and the
/// pipelined forms (docs/protocol.md, "Pipelining"): a load naming its own <c>scene_id</c>, the same id loaded twice,
/// requests that name a scene before or after its load.
/// </summary>
public sealed class ServeRequestTarget : FuzzTarget
{
    /// <summary>How many lines of one input are served (the rest is ignored).</summary>
    public const int MaxLines = 8;

    private static readonly string[] Tokens =
    [
        "\"op\"", "\"hello\"", "\"protocol\"", "\"blockid_to_lcoord\"", "\"gid_to_lcoord\"", "\"lcoord_to_gid\"", "\"inbound_valid_cellid\"",
        "\"get_outside_lcoord\"", "\"adjust_to_outside\"", "\"outside_cells\"", "\"find_cell\"", "\"find_cell_scene\"", "\"outside_cells_parts\"",
        "\"load_scene\"", "\"unload_scene\"", "\"scene_id\"", "\"s1\"", "\"pipeline\"", "\"t1\"", "\"scene\"", "\"dat\"", "\"manifest\"", "\"records\"", "\"cell\"",
        "\"current\"", "\"load_cells\"", "\"find_cell_walk\"", "\"origin\"", "\"body\"", "\"steps\"", "\"spheres\"", "\"parts\"", "\"x\"", "\"y\"", "\"z\"", "\"r\"", "\"0x7F7F0001\"", "\"0xFFFF0100\"",
        "\"NaN\"", "\"Infinity\"", "\"-Infinity\"", "null", "true", "false", "1e39", "-0", "2147483648", "\\u0000", "\\ud800",
        "[", "]", "{", "}", ":", ",", "\n",
    ];

    /// <inheritdoc/>
    public override string Name => "serve-request";

    /// <inheritdoc/>
    public override string Description => "the serve request parser (ProtocolServer.AnswerChecked over the reference, up to 8 lines); bad requests must get an error answer, nothing may escape";

    /// <inheritdoc/>
    public override TargetKind Kind => TargetKind.Parser;

    /// <inheritdoc/>
    public override bool MayHang => true; // a scene or a long sphere list runs real physics

    /// <inheritdoc/>
    public override IReadOnlyList<string> Dictionary => Tokens;

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = BuildSeeds();

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(string? fault)
    {
        NoFault(fault);
        return data =>
        {
            var server = new ProtocolServer(ReferenceAdapter.Instance);
            var bytesServer = new ProtocolServer(ReferenceAdapter.Instance); // fed the same lines as bytes, as serve reads them
            byte[] all = data.ToArray();
            int from = 0;
            for (int n = 0; n < MaxLines && from <= all.Length; n++)
            {
                int end = Array.IndexOf(all, (byte)'\n', from);
                var raw = all.AsMemory(from, (end < 0 ? all.Length : end) - from);
                from = end < 0 ? all.Length + 1 : end + 1;
                string line = Encoding.UTF8.GetString(raw.Span);
                if (line.Length == 0)
                {
                    continue; // serve skips empty lines
                }

                string answer = server.AnswerChecked(line);
                string fromBytes = bytesServer.AnswerChecked(raw);
                if (fromBytes != answer)
                {
                    throw new InvalidOperationException($"serve-request: the request's bytes were answered {Wire.Brief(fromBytes, 200)}, its text {Wire.Brief(answer, 200)}");
                }

                try
                {
                    Wire.Parse(answer).Dispose();
                }
                catch (WireException e)
                {
                    throw new InvalidOperationException($"serve-request: the answer is not one JSON object ({e.Message}): {Wire.Brief(answer, 200)}", e);
                }
            }
        };
    }

    private static Dictionary<string, byte[]> BuildSeeds()
    {
        var cottage = SceneKit.Cottage(new CottagePlan((192.0 * 0x40) + 50, (192.0 * 0x41) + 60, 0.5f, 2, 6, 5, 0x5A, BackDoor: true, Storey: false));
        var cell = new CellId(0x40410012);
        Sphere[] body = [new Sphere(new Vector3(50, 60, 0.5f), 0.5f), new Sphere(new Vector3(50, 60, 1.5f), 0.5f)];
        string FindCell(Action<Utf8JsonWriter> where) => Wire.Line(w =>
        {
            w.WriteString("op", "find_cell");
            where(w);
            Wire.WriteCell(w, "cell", cell);
            Wire.WriteSpheres(w, "spheres", body);
            w.WriteNull("current");
        });

        string LoadWithId(string id, Action<Utf8JsonWriter> scene) => Wire.Line(w =>
        {
            w.WriteString("op", "load_scene");
            w.WriteString("scene_id", id);
            scene(w);
        });
        string SceneWalk(string id, Vector2[] steps, bool loadCells) => Wire.Line(w =>
        {
            w.WriteString("op", "find_cell_walk");
            w.WriteString("scene_id", id);
            WalkWire.WriteFields(w, new WalkRequest(cottage, cell, new Vector3(50, 60, 0), body, steps) { LoadCells = loadCells });
        });
        static string Unload(string id) => Wire.Line(w =>
        {
            w.WriteString("op", "unload_scene");
            w.WriteString("scene_id", id);
        });
        static void SceneField(Utf8JsonWriter w, Scene scene)
        {
            w.WritePropertyName("scene");
            w.WriteRawValue(SceneJson.WriteCompact(scene));
        }

        var lines = new Dictionary<string, string>
        {
            ["hello"] = Wire.Line(w =>
            {
                w.WriteString("op", "hello");
                w.WriteNumber("protocol", Wire.Version);
            }),
            ["blockid-to-lcoord"] = Wire.Line(w =>
            {
                w.WriteString("op", "blockid_to_lcoord");
                Wire.WriteCell(w, "cell", new CellId(0x7F7F0001));
            }),
            ["lcoord-to-gid"] = Wire.Line(w =>
            {
                w.WriteString("op", "lcoord_to_gid");
                w.WriteNumber("x", 2039);
                w.WriteNumber("y", -1);
            }),
            ["adjust-to-outside"] = Wire.Line(w =>
            {
                w.WriteString("op", "adjust_to_outside");
                Wire.WriteCell(w, "cell", new CellId(0x3A240031));
                Wire.WriteFloat(w, "x", 191.99998f);
                Wire.WriteFloat(w, "y", float.NaN);
            }),
            ["outside-cells"] = Wire.Line(w =>
            {
                w.WriteString("op", "outside_cells");
                Wire.WriteCell(w, "cell", cell);
                Wire.WriteSpheres(w, "spheres", body);
            }),
            ["find-cell-land"] = FindCell(_ => { }),
            ["find-cell-scene"] = FindCell(w =>
            {
                w.WritePropertyName("scene");
                w.WriteRawValue(SceneJson.WriteCompact(cottage));
            }),
            ["load-find-unload"] = string.Join(
                '\n',
                Wire.Line(w =>
                {
                    w.WriteString("op", "load_scene");
                    w.WritePropertyName("scene");
                    w.WriteRawValue(SceneJson.WriteCompact(cottage));
                }),
                FindCell(w => w.WriteString("scene_id", "s1")),
                Wire.Line(w =>
                {
                    w.WriteString("op", "unload_scene");
                    w.WriteString("scene_id", "s1");
                })),
            ["load-dat"] = Wire.Line(w =>
            {
                w.WriteString("op", "load_scene");
                DatWire.WriteScene(w, "dat", SceneKit.Dungeon(new DungeonPlan((192.0 * 0x20) + 150, (192.0 * 0x21) + 30, 2, 8, 0, 0x33)));
            }),
            ["walk-land"] = Wire.Line(w =>
            {
                w.WriteString("op", "find_cell_walk");
                w.WriteNull("scene");
                WalkWire.WriteFields(w, new WalkRequest(null, cell, new Vector3(50, 60, 0), body, [new Vector2(150, 0), new Vector2(-0.25f, 200)]));
            }),
            ["load-walk-unload"] = string.Join(
                '\n',
                Wire.Line(w =>
                {
                    w.WriteString("op", "load_scene");
                    w.WritePropertyName("scene");
                    w.WriteRawValue(SceneJson.WriteCompact(cottage));
                }),
                Wire.Line(w =>
                {
                    w.WriteString("op", "find_cell_walk");
                    w.WriteString("scene_id", "s1");
                    WalkWire.WriteFields(w, new WalkRequest(cottage, cell, new Vector3(50, 60, 0), body, [new Vector2(3, 0), new Vector2(0, 3)]) { LoadCells = true });
                }),
                Wire.Line(w =>
                {
                    w.WriteString("op", "unload_scene");
                    w.WriteString("scene_id", "s1");
                })),
            ["pipelined-client-ids"] = string.Join(
                '\n',
                SceneWalk("t1", [new Vector2(3, 0)], false), // named before its load: unknown
                LoadWithId("t1", w => DatWire.WriteScene(w, "dat", cottage)),
                LoadWithId("t1", w => SceneField(w, cottage)), // the same id again: refused
                FindCell(w => w.WriteString("scene_id", "t1")),
                SceneWalk("t1", [new Vector2(3, 0), new Vector2(0, 3)], true),
                Unload("t1"),
                LoadWithId(string.Empty, w => SceneField(w, cottage))), // an empty id: refused
            ["not-an-object"] = "[1,2,3]",
        };
        return lines.ToDictionary(kv => kv.Key, kv => Encoding.UTF8.GetBytes(kv.Value));
    }
}
