using System.Runtime.CompilerServices;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Protocol;

/// <summary>
/// An implementation in another process, in any language, behind <see cref="ICellPhysics"/>: protocol v1 over the
/// child's stdin/stdout (docs/protocol.md). A crash, a hang past the timeout or an answer that is not protocol v1 is an
/// <see cref="AdapterFailureException"/> (exit 2); <c>{"error": ...}</c> to an announced op is a finding.
/// </summary>
/// <remarks>Calls are serialised (one request in flight), so the adapter is safe to share between threads.</remarks>
public sealed class ProcessAdapter : ICellPhysics, IDisposable
{
    private readonly LineProcess child;
    private readonly TimeSpan timeout;
    private const int KeptScenes = 8;
    private readonly Lock gate = new();
    private readonly List<(Scene Scene, string Id)> loaded = [];

    // Scenes are immutable records: serialise each once, however many steps of a walk query it.
    private static readonly ConditionalWeakTable<Scene, string> CompactScenes = [];

    private ProcessAdapter(LineProcess child, TimeSpan timeout, string name, Op ops, PickPolicy pick, IReadOnlyList<string> unknownOps)
    {
        this.child = child;
        this.timeout = timeout;
        Name = name;
        Ops = ops;
        Pick = pick;
        UnknownOps = unknownOps;
    }

    /// <inheritdoc/>
    public string Name { get; }

    /// <inheritdoc/>
    public Op Ops { get; }

    /// <inheritdoc/>
    public PickPolicy Pick { get; }

    /// <inheritdoc/>
    public IndoorFidelity Indoor { get; private init; }

    /// <inheritdoc/>
    public OutdoorFidelity Outdoor { get; private init; }

    /// <summary>Gets a value indicating whether the implementation declared <c>"frame": "world"</c>: points travel in world coordinates (<see cref="WorldFrame"/>).</summary>
    public bool InWorldFrame { get; private init; }

    /// <summary>Gets op names the implementation announced that protocol v1 does not know (ignored).</summary>
    public IReadOnlyList<string> UnknownOps { get; }

    /// <summary>Gets the last lines the implementation wrote to stderr.</summary>
    public IReadOnlyList<string> StderrTail => child.StderrTail;

    /// <summary>Starts the implementation and performs the <c>hello</c> handshake.</summary>
    /// <param name="commandLine">The command line (run through <c>/bin/sh -c</c>, or <c>cmd /c</c> on Windows).</param>
    /// <param name="options">Timeout and stderr handling.</param>
    /// <returns>The adapter.</returns>
    /// <exception cref="AdapterFailureException">It could not be started or did not complete the handshake.</exception>
    public static ProcessAdapter Start(string commandLine, ProcessAdapterOptions? options = null)
    {
        options ??= new ProcessAdapterOptions();
        var child = LineProcess.Start(commandLine, options.StderrSink, options.MaxLineBytes);
        try
        {
            string answer = child.Exchange(
                Wire.Line(w =>
                {
                    w.WriteString("op", "hello");
                    w.WriteNumber("protocol", Wire.Version);
                }),
                "hello",
                options.Timeout > options.HandshakeTimeout ? options.Timeout : options.HandshakeTimeout);
            using var doc = ParseAnswer(answer, "hello", commandLine);
            var hello = doc.RootElement;
            if (hello.TryGetProperty("error", out var error))
            {
                throw new AdapterFailureException($"'{commandLine}' refused the handshake: {Wire.Show(error)}");
            }

            try
            {
                int protocol = Wire.ReadInt(hello, "protocol");
                if (protocol != Wire.Version)
                {
                    throw new AdapterFailureException($"'{commandLine}' speaks protocol {protocol}; this tool speaks {Wire.Version}");
                }

                // The name is the implementation's text: escaped and cut once here, so every report quotes it safely (issue 28).
                string name = Values.InputQuote.Line(hello.TryGetProperty("name", out _) ? Wire.ReadString(hello, "name") : commandLine, 120);
                var opsField = Wire.Field(hello, "ops");
                if (opsField.ValueKind != JsonValueKind.Array || opsField.EnumerateArray().Any(e => e.ValueKind != JsonValueKind.String))
                {
                    throw new WireException("field \"ops\" must be an array of op names");
                }

                var ops = OpNames.Parse(opsField.EnumerateArray().Select(e => e.GetString()!), out var unknown);
                string? pickName = hello.TryGetProperty("pick", out var p) && p.ValueKind != JsonValueKind.Null ? Wire.ReadString(hello, "pick") : null;
                if (!PickNames.TryParse(pickName, out var pick))
                {
                    throw new WireException($"unknown pick \"{pickName}\" (known: retail, current-first)");
                }

                var declared = hello.TryGetProperty("fidelity", out var fid) && fid.ValueKind != JsonValueKind.Null ? fid : default;
                if (declared.ValueKind != JsonValueKind.Undefined && (declared.ValueKind != JsonValueKind.Array || declared.EnumerateArray().Any(e => e.ValueKind != JsonValueKind.String)))
                {
                    throw new WireException("field \"fidelity\" must be an array of deviation names");
                }

                var names = declared.ValueKind == JsonValueKind.Array ? declared.EnumerateArray().Select(e => e.GetString()!).ToArray() : [];
                if (!FidelityNames.TryParse(names, out var indoor, out var outdoor, out var bad))
                {
                    throw new WireException($"unknown fidelity \"{Wire.Brief(bad!, 60)}\" (known: {string.Join(", ", FidelityNames.Known)})");
                }

                string frame = hello.TryGetProperty("frame", out var f) && f.ValueKind != JsonValueKind.Null ? Wire.ReadString(hello, "frame") : "block";
                if (frame is not ("block" or WorldFrame.Name))
                {
                    throw new WireException($"unknown frame \"{Wire.Brief(frame, 40)}\" (known: block, world)");
                }

                return new ProcessAdapter(child, options.Timeout, name, ops, pick, unknown) { Indoor = indoor, Outdoor = outdoor, InWorldFrame = frame == WorldFrame.Name };
            }
            catch (WireException e)
            {
                throw new AdapterFailureException($"'{commandLine}' answered the handshake with something that is not protocol v1: {e.Message}. Answer: {Wire.Brief(answer, 200)}", e);
            }
        }
        catch
        {
            child.Dispose();
            throw;
        }
    }

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => LcoordAnswer(Op.BlockIdToLcoord, w => Wire.WriteCell(w, "cell", id), out lcoord);

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord) => LcoordAnswer(Op.GidToLcoord, w => Wire.WriteCell(w, "cell", id), out lcoord);

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => Call(
        Op.LcoordToGid,
        w =>
        {
            w.WriteNumber("x", x);
            w.WriteNumber("y", y);
        },
        a => Wire.ReadCell(a, "cell"));

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => Call(Op.InboundValidCellId, w => Wire.WriteCell(w, "cell", id), a => Wire.ReadBool(a, "ok"));

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => LcoordAnswer(
        Op.GetOutsideLcoord,
        w =>
        {
            Wire.WriteCell(w, "cell", id);
            Wire.WriteFloat(w, "x", x);
            Wire.WriteFloat(w, "y", y);
        },
        out lcoord);

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y) => Call(
        Op.AdjustToOutside,
        w =>
        {
            Wire.WriteCell(w, "cell", id);
            Wire.WriteFloat(w, "x", x);
            Wire.WriteFloat(w, "y", y);
        },
        a => new AdjustResult(Wire.ReadBool(a, "ok"), Wire.ReadCell(a, "cell"), Wire.ReadFloat(a, "x"), Wire.ReadFloat(a, "y")));

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => OutsideCells(cell, System.Numerics.Vector3.Zero, spheres);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres) => Call(
        Op.OutsideCells,
        w =>
        {
            Wire.WriteCell(w, "cell", cell);
            Wire.WriteSpheres(w, "spheres", spheres);
            Wire.WriteOrigin(w, origin, spheres);
        },
        a => Wire.ReadCells(a, "cells"));

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(cell, System.Numerics.Vector3.Zero, spheres, current);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) =>
        Call(Op.FindCell, w =>
        {
            FindCellFields(w, null, cell, spheres, current);
            Wire.WriteOrigin(w, origin, spheres);
        }, ReadFindCell);

    /// <summary>
    /// <c>find_cell</c> with a scene: the scene travels as its compact JSON (docs/protocol.md, "Scenes") and is
    /// served only by an implementation that announced <c>find_cell_scene</c>; a null scene is open land.
    /// </summary>
    /// <param name="scene">The scene, or null for open land.</param>
    /// <param name="cell">The position's cell.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <returns>The candidates and the containing cell.</returns>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) =>
        scene is null
            ? FindCell(cell, spheres, current)
            : Call(Op.FindCellScene, "find_cell", w => FindCellFields(w, scene, cell, spheres, current), ReadFindCell);

    /// <summary><c>find_cell</c> with <c>"load_cells": true</c> (a movement transition, no visibility filter), for an implementation that announced <c>find_cell_transition</c>.</summary>
    /// <param name="scene">The scene, or null for open land.</param>
    /// <param name="cell">The position's cell.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <param name="loadCells">True for a transition query.</param>
    /// <returns>The candidates and the containing cell.</returns>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
        !loadCells
            ? FindCell(scene, cell, spheres, current)
            : Call(Op.FindCellTransition, "find_cell", w =>
            {
                FindCellFields(w, scene, cell, spheres, current);
                w.WriteBoolean("load_cells", true);
            }, ReadFindCell);

    /// <summary>
    /// <c>find_cell_walk</c>: the whole walk in one round trip when the implementation announced it (docs/protocol.md,
    /// "Whole walks"); otherwise, or for a walk longer than <see cref="WalkWire.MaxSteps"/>, query by query as before.
    /// </summary>
    /// <param name="walk">The walk.</param>
    /// <returns>One answer per query.</returns>
    public IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk)
    {
        if ((Ops & Op.FindCellWalk) == 0 || walk.Steps.Count > WalkWire.MaxSteps || InWorldFrame) // a world-frame port is asked query by query
        {
            return WalkThread.AskEach(this, walk);
        }

        // The op a step-by-step walk would need: a missing one is NotSupportedException, as it is there.
        var needs = walk.LoadCells ? Op.FindCellTransition : walk.Scene is null ? Op.FindCell : Op.FindCellScene;
        return Call(
            needs,
            "find_cell_walk",
            w =>
            {
                SceneField(w, walk.Scene);
                WalkWire.WriteFields(w, walk);
            },
            a => WalkWire.ReadAnswer(a, walk.Queries));
    }

    private void FindCellFields(Utf8JsonWriter w, Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current)
    {
        SceneField(w, scene);

        Wire.WriteCell(w, "cell", cell);
        Wire.WriteSpheres(w, "spheres", spheres);
        if (current.IsNone)
        {
            w.WriteNull("current");
        }
        else
        {
            Wire.WriteCell(w, "current", current);
        }
    }

    private void SceneField(Utf8JsonWriter w, Scene? scene)
    {
        if (scene is null)
        {
            w.WriteNull("scene");
        }
        else if ((Ops & Op.LoadScene) != 0)
        {
            w.WriteString("scene_id", SceneId(scene));
        }
        else
        {
            WriteScene(w, scene);
        }
    }

    private static FindCellResult ReadFindCell(JsonElement a) => Wire.ReadFindCell(a);

    // The scene as its compact JSON, serialised once per scene instance.
    private static void WriteScene(Utf8JsonWriter w, Scene scene)
    {
        w.WritePropertyName("scene");
        w.WriteRawValue(CompactScenes.GetValue(scene, SceneJson.WriteCompact), skipInputValidation: true);
    }

    // load_scene once per scene: the most recent few stay loaded (a walk, its translated copy, a shrink step's
    // neighbours), the oldest is unloaded to make room.
    private string SceneId(Scene scene)
    {
        lock (loaded)
        {
            int at = loaded.FindIndex(e => ReferenceEquals(e.Scene, scene));
            if (at >= 0)
            {
                var hit = loaded[at];
                loaded.RemoveAt(at);
                loaded.Add(hit);
                return hit.Id;
            }

            if (loaded.Count == KeptScenes)
            {
                string old = loaded[0].Id;
                loaded.RemoveAt(0);
                Call(Op.LoadScene, "unload_scene", w => w.WriteString("scene_id", old), a => Wire.ReadBool(a, "ok"));
            }

            string id = Call(
                Op.LoadScene,
                "load_scene",
                w =>
                {
                    if ((Ops & Op.DatRecords) != 0)
                    {
                        DatWire.WriteScene(w, "dat", scene);
                    }
                    else
                    {
                        WriteScene(w, scene);
                    }
                },
                a => Wire.ReadString(a, "scene_id"));
            loaded.Add((scene, id));
            return id;
        }
    }

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => Call(
        Op.OutsideCellsParts,
        w => PartWire.WriteParts(w, "parts", parts),
        a => Wire.ReadCells(a, "cells"));

    /// <inheritdoc/>
    public void Dispose() => child.Dispose();

    // The whole error text, escaped as JSON escapes it: the failure file keeps all of it, the console line cuts it.
    private static string ErrorText(JsonElement error) =>
        Values.InputQuote.TryText(error) is { } text ? "\"" + Values.InputQuote.Escape(text) + "\"" : Wire.Show(error);

    private static JsonDocument ParseAnswer(string answer, string op, string who)
    {
        try
        {
            return Wire.Parse(answer);
        }
        catch (WireException e)
        {
            throw new AdapterFailureException($"'{who}' answered '{op}' with something that is not protocol v1 ({e.Message}): {Wire.Brief(answer, 200)}", e);
        }
    }

    private bool LcoordAnswer(Op op, Action<Utf8JsonWriter> fields, out Lcoord lcoord)
    {
        var (ok, x, y) = Call(op, fields, a => (Wire.ReadBool(a, "ok"), Wire.ReadInt(a, "x"), Wire.ReadInt(a, "y")));
        lcoord = new Lcoord(x, y);
        return ok;
    }

    private T Call<T>(Op op, Action<Utf8JsonWriter> fields, Func<JsonElement, T> read) => Call(op, OpNames.Names(op)[0], fields, read);

    private T Call<T>(Op op, string name, Action<Utf8JsonWriter> fields, Func<JsonElement, T> read)
    {
        if ((Ops & op) == 0)
        {
            throw new NotSupportedException($"{Name} does not offer {OpNames.Names(op)[0]}");
        }

        string request = Wire.Line(w =>
        {
            w.WriteString("op", name);
            fields(w);
        });
        request = InWorldFrame ? WorldFrame.ToWorld(request) : request;

        lock (gate)
        {
            string answer = child.Exchange(request, name, timeout);
            using var doc = ParseAnswer(answer, name, Name);
            if (doc.RootElement.TryGetProperty("error", out var error))
            {
                throw new ImplementationErrorException($"{name} answered error {ErrorText(error)}");
            }

            try
            {
                return read(doc.RootElement);
            }
            catch (WireException e)
            {
                throw new AdapterFailureException($"'{Name}' answered '{name}' with something that is not protocol v1: {e.Message}. Request: {Wire.Brief(request, 200)} Answer: {Wire.Brief(answer, 200)}", e);
            }
        }
    }
}
