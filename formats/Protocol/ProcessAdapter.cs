using System.Runtime.CompilerServices;
using System.Runtime.ExceptionServices;
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
    private readonly Lazy<ICellPhysics> guesser;
    private readonly Reported[] reported = [new(), new()]; // [0] open land, [1] scenes
    private PipelineSession? session;
    private int chosenIds;
    private bool probing;
    private readonly List<string> differences = [];

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
        guesser = new(() => new ReferenceAdapter(Pick, outdoor: Outdoor) { Indoor = Indoor });
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

    /// <summary>Gets a value indicating whether the implementation announced <c>pipeline</c>: <see cref="Pipelined{T}"/> then speculates and streams.</summary>
    /// <remarks>A world-frame child too: a point it cannot be sent (UnposableQueryException) is refused before the
    /// pipeline counts the query (<see cref="RefuseUnposable"/>), in every pass alike.</remarks>
    public bool Pipelines => (Ops & Op.Pipeline) != 0;

    /// <summary>Gets how many runs went through <see cref="Pipelined{T}"/> with the pipeline, and how many of them had to be replayed (an answer differed from its guess).</summary>
    public (int Runs, int Replays) PipelineCounts { get; private set; }

    /// <summary>Gets, for the first few replayed runs, the answer that differed from its guess (why the run was replayed).</summary>
    public IReadOnlyList<string> PipelineDifferences => differences;

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

                if (indoor.AceKeepsStaleCells && SceneQueryKinds.OffersScenes(ops) && ((ops & Op.FindCellWalk) == 0 || frame == WorldFrame.Name))
                {
                    // The stale array lives for one walk (facts §7 #6; docs/conformance.md, "Declared modes"): a port asked
                    // query by query cannot tell where a walk begins, so its answers could not be judged.
                    throw new AdapterFailureException($"'{commandLine}' declares ace-keeps-stale-cells but is asked query by query ({(frame == WorldFrame.Name ? "world frame" : "no find_cell_walk")}): the stale array lives for one walk, so a port declaring it must announce find_cell_walk in the block frame (docs/conformance.md, \"Declared modes\")");
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

    /// <summary>
    /// Runs <paramref name="run"/> (one invariant's whole run: its cases, shrinking and re-checks) against a child that
    /// announced <c>pipeline</c> without waiting for each answer: every query is answered at once with a guess (the
    /// reference in the declared mode) and streamed to the child, whose answers are compared as they arrive. When every
    /// answer equalled its guess, that result is the live run's; otherwise <paramref name="run"/> runs again with the
    /// answers before the first difference replayed, the differing one as the child gave it, and the rest guessed and
    /// streamed again (live after a few differences) — the same result as a live run (docs/protocol.md, "Pipelining").
    /// Without <c>pipeline</c> it just runs.
    /// </summary>
    /// <typeparam name="T">The run's result.</typeparam>
    /// <param name="run">The run; called again after each pass in which an answer differed (what an earlier call reported is to be discarded).</param>
    /// <returns>The result.</returns>
    /// <remarks>The adapter must be used from the calling thread only while it runs.</remarks>
    public T Pipelined<T>(Func<T> run)
    {
        if (!Pipelines || session is not null)
        {
            return run();
        }

        List<string> ids;
        lock (loaded)
        {
            ids = [.. loaded.Select(e => e.Id)];
        }

        using var s = new PipelineSession(child, timeout, ids);
        session = s;
        try
        {
            for (int pass = 1; ; pass++)
            {
                T result = default!;
                ExceptionDispatchInfo? thrown = null;
                try
                {
                    long r = WireProfile.Start();
                    result = run();
                    WireProfile.Stop("tool: pipelined runs (all)", r);
                }
                catch (Exception e) when (e is not OutOfMemoryException)
                {
                    thrown = ExceptionDispatchInfo.Capture(e);
                }

                long f = WireProfile.Start();
                bool stands = s.Finish();
                WireProfile.Stop("tool: pass end, waiting for the child", f);
                if (stands)
                {
                    PipelineCounts = (PipelineCounts.Runs + 1, PipelineCounts.Replays + (pass > 1 ? 1 : 0));
                    thrown?.Throw();
                    return result;
                }

                if (differences.Count < 5 && s.Difference is { } why)
                {
                    differences.Add(why);
                }

                s.NextPass(UnloadQuietly);
                lock (loaded)
                {
                    loaded.Clear();
                }
            }
        }
        finally
        {
            session = null;
        }
    }

    // After a difference: the child may hold scenes the first pass loaded; an unknown id is no finding here.
    private void UnloadQuietly(string id)
    {
        try
        {
            Live("unload_scene", Request("unload_scene", w => w.WriteString("scene_id", id)), a => Wire.ReadBool(a, "ok"));
        }
        catch (ImplementationErrorException)
        {
            // Not loaded after all (its load was refused): nothing to unload.
        }
    }

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => LcoordAnswer(Op.BlockIdToLcoord, w => Wire.WriteCell(w, "cell", id), r => (r.BlockIdToLcoord(id, out var l), l.X, l.Y), out lcoord);

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord) => LcoordAnswer(Op.GidToLcoord, w => Wire.WriteCell(w, "cell", id), r => (r.GidToLcoord(id, out var l), l.X, l.Y), out lcoord);

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => Call(
        Op.LcoordToGid,
        w =>
        {
            w.WriteNumber("x", x);
            w.WriteNumber("y", y);
        },
        a => Wire.ReadCell(a, "cell"),
        r => r.LcoordToGid(x, y));

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => Call(Op.InboundValidCellId, w => Wire.WriteCell(w, "cell", id), a => Wire.ReadBool(a, "ok"), r => r.InboundValidCellId(id));

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => LcoordAnswer(
        Op.GetOutsideLcoord,
        w =>
        {
            Wire.WriteCell(w, "cell", id);
            Wire.WriteFloat(w, "x", x);
            Wire.WriteFloat(w, "y", y);
        },
        r => (r.GetOutsideLcoord(id, x, y, out var l), l.X, l.Y),
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
        a => new AdjustResult(Wire.ReadBool(a, "ok"), Wire.ReadCell(a, "cell"), Wire.ReadFloat(a, "x"), Wire.ReadFloat(a, "y")),
        r => r.AdjustToOutside(id, x, y));

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
        a => Wire.ReadCells(a, "cells"),
        r => r.OutsideCells(cell, origin, spheres));

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(cell, System.Numerics.Vector3.Zero, spheres, current);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) =>
        Call(Op.FindCell, w =>
        {
            FindCellFields(w, null, cell, spheres, current);
            Wire.WriteOrigin(w, origin, spheres);
        }, a => Learn(Wire.ReadFindCell(a), false), r => Project(r.FindCell(cell, origin, spheres, current), false));

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
            : Call(Op.FindCellScene, "find_cell", w => FindCellFields(w, scene, cell, spheres, current), a => Learn(Wire.ReadFindCell(a), true), r => Project(r.FindCell(scene, cell, spheres, current), true));

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
            }, a => Learn(Wire.ReadFindCell(a), scene is not null), r => Project(r.FindCell(scene, cell, spheres, current, true), scene is not null));

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
            a => LearnAll(WalkWire.ReadAnswer(a, walk.Queries), walk.Scene is not null),
            r => ProjectAll(r.FindCellWalk(walk), walk.Scene is not null) is var g && g.Count == walk.Queries
                ? g
                : throw new InvalidOperationException("the reference answered the walk with another number of queries")); // no guess: asked and read as the child answers
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
        if (scene is null || probing)
        {
            w.WriteNull("scene"); // probing: no scene is loaded for a request that is only converted (RefuseUnposable)
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

    // The scene as its compact JSON, serialised once per scene instance.
    private static void WriteScene(Utf8JsonWriter w, Scene scene)
    {
        w.WritePropertyName("scene");
        w.WriteRawValue(CompactScenes.GetValue(scene, SceneJson.WriteCompact), skipInputValidation: true);
    }

    // load_scene once per scene: the most recent few stay loaded (a walk, its translated copy, a shrink step's
    // neighbours), the oldest is unloaded to make room. To a pipelining child the tool chooses the id (docs/protocol.md,
    // "Pipelining"), so a find_cell can name a scene whose load is still in flight.
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
                Transport("unload_scene", w => w.WriteString("scene_id", old), a => Wire.ReadBool(a, "ok"), true, null, old);
            }

            string? chosen = Pipelines ? "t" + (++chosenIds).ToString(System.Globalization.CultureInfo.InvariantCulture) : null;
            string id = Transport(
                "load_scene",
                w =>
                {
                    if (chosen is not null)
                    {
                        w.WriteString("scene_id", chosen);
                    }

                    if ((Ops & Op.DatRecords) != 0)
                    {
                        DatWire.WriteScene(w, "dat", scene);
                    }
                    else
                    {
                        WriteScene(w, scene);
                    }
                },
                a => Wire.ReadString(a, "scene_id") is var answered && (chosen is null || answered == chosen)
                    ? answered
                    : throw new WireException($"load_scene answered scene_id \"{Wire.Brief(answered, 40)}\" for the id \"{chosen}\" the tool chose (a pipelining implementation keeps the client's id)"),
                chosen ?? string.Empty,
                chosen,
                null);
            loaded.Add((scene, id));
            return id;
        }
    }

    /// <inheritdoc/>
    /// <exception cref="UnposableQueryException">A part protocol v1 cannot carry (more than a block from the first part, or out of the wire's bounds): the case is not judged, as a correct child must refuse it (PartBounds).</exception>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts)
    {
        ArgumentNullException.ThrowIfNull(parts);

        // Refused before it is asked or counted (as RefuseUnposable): a pipelined pass must not pair answers with it.
        for (int i = 0; i < parts.Count; i++)
        {
            if (Values.PartBounds.Problem(parts[i], parts[0]) is var (field, problem))
            {
                throw new UnposableQueryException($"parts[{i}].{field}: {problem}: protocol v1 cannot carry this query (docs/protocol.md); case not judged");
            }
        }

        return Call(
            Op.OutsideCellsParts,
            w => PartWire.WriteParts(w, "parts", parts),
            a => Wire.ReadCells(a, "cells"),
            r => r.OutsideCellsParts(parts));
    }

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

    private bool LcoordAnswer(Op op, Action<Utf8JsonWriter> fields, Func<ICellPhysics, (bool, int, int)> guess, out Lcoord lcoord)
    {
        var (ok, x, y) = Call(op, fields, a => (Wire.ReadBool(a, "ok"), Wire.ReadInt(a, "x"), Wire.ReadInt(a, "y")), guess);
        lcoord = new Lcoord(x, y);
        return ok;
    }

    private T Call<T>(Op op, Action<Utf8JsonWriter> fields, Func<JsonElement, T> read, Func<ICellPhysics, T> guess) => Call(op, OpNames.Names(op)[0], fields, read, guess);

    // One query: live (a round trip), or within a pipelined run (Pipelined) guessed and streamed.
    private T Call<T>(Op op, string name, Action<Utf8JsonWriter> fields, Func<JsonElement, T> read, Func<ICellPhysics, T> guess)
    {
        if ((Ops & op) == 0)
        {
            throw new NotSupportedException($"{Name} does not offer {OpNames.Names(op)[0]}");
        }

        if (InWorldFrame)
        {
            RefuseUnposable(name, fields);
        }

        return session is { } s
            ? s.Query(name, () => Streamed(name, fields), (request, answer) => Interpret(name, request, answer, read), () => WireProfile.Time("tool: guess (reference, incl. its scene build)", () => guess(guesser.Value)), () => Live(name, Request(name, fields), read))
            : Live(name, Request(name, fields), read);
    }

    // A world-frame point a double cannot carry exactly (WorldFrame) is refused before the query is asked or counted:
    // a pipelined pass that counted it would pair every later answer with the wrong query (false failures at base seed
    // 7700123001), and one that skipped it in the first pass only would replay another run. The request is written
    // without its scene (nothing is loaded) and converted; its points are all the conversion reads.
    private void RefuseUnposable(string name, Action<Utf8JsonWriter> fields)
    {
        probing = true;
        try
        {
            _ = WorldFrame.ToWorld(Wire.Line(w =>
            {
                w.WriteString("op", name);
                fields(w);
            }));
        }
        finally
        {
            probing = false;
        }
    }

    // A scene load or unload: transport, streamed within a pipelined run's first pass, live otherwise.
    private T Transport<T>(string name, Action<Utf8JsonWriter> fields, Func<JsonElement, T> read, T guess, string? loads, string? unloads)
    {
        if ((Ops & Op.LoadScene) == 0)
        {
            throw new NotSupportedException($"{Name} does not offer load_scene");
        }

        return session is { Streaming: true } s
            ? s.Transport(name, Streamed(name, fields), (r, answer) => Interpret(name, r, answer, read), guess, loads, unloads)
            : Live(name, Request(name, fields), read);
    }

    // Every request line, streamed or awaited; a world-frame child gets its points in world coordinates (WorldFrame).
    private string Request(string name, Action<Utf8JsonWriter> fields)
    {
        string request = Written(name, fields, Wire.Line);
        return InWorldFrame ? WorldFrame.ToWorld(request) : request;
    }

    // A streamed request: its bytes as written (text only when quoted), or the converted text for a world-frame child.
    private RequestLine Streamed(string name, Action<Utf8JsonWriter> fields) =>
        InWorldFrame ? new RequestLine(Request(name, fields)) : new RequestLine(Written(name, fields, Wire.LineUtf8));

    // The op and its fields as one line (text or bytes), timed when profiling.
    private static T Written<T>(string name, Action<Utf8JsonWriter> fields, Func<Action<Utf8JsonWriter>, T> line)
    {
        long t = WireProfile.Start();
        var written = line(w =>
        {
            w.WriteString("op", name);
            fields(w);
        });
        if (WireProfile.On)
        {
            WireProfile.Stop("tool: request line (" + name + ", nested)", t);
        }

        return written;
    }

    private T Live<T>(string name, string request, Func<JsonElement, T> read)
    {
        lock (gate)
        {
            return Interpret(name, request, child.Exchange(request, name, timeout), read);
        }
    }

    // An answer line as a call reads it: the value, a finding ({"error": ...}) or a protocol failure (exit 2).
    private T Interpret<T>(string name, string request, string answer, Func<JsonElement, T> read)
    {
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

    // The optional find_cell fields (loaded, hits_interior_cell) a child reports are learnt from its first answer, on
    // open land and in scenes apart; a guess carries only those, since the answer read from the child has only those.
    private FindCellResult Learn(FindCellResult answer, bool scene)
    {
        reported[scene ? 1 : 0].Learn(answer);
        return answer;
    }

    private IReadOnlyList<FindCellResult> LearnAll(IReadOnlyList<FindCellResult> answers, bool scene)
    {
        if (answers.Count > 0)
        {
            Learn(answers[0], scene);
        }

        return answers;
    }

    private FindCellResult Project(FindCellResult guess, bool scene) => reported[scene ? 1 : 0].Project(guess);

    private IReadOnlyList<FindCellResult> ProjectAll(IReadOnlyList<FindCellResult> guesses, bool scene)
    {
        if (reported[scene ? 1 : 0].ReportsAll)
        {
            return guesses; // every optional field reported: the guesses as they are (issue 26: a copy per step cost the main thread)
        }

        var projected = new FindCellResult[guesses.Count];
        for (int i = 0; i < projected.Length; i++)
        {
            projected[i] = Project(guesses[i], scene);
        }

        return projected;
    }

    // Which optional fields a child's find_cell answers carry: unknown until its first answer (a guess cannot be made
    // before, so that query is asked and awaited), then fixed.
    private sealed class Reported
    {
        private int state = -1; // -1 unknown; else bit 0: loaded, bit 1: hits_interior_cell

        public void Learn(FindCellResult answer) =>
            Interlocked.CompareExchange(ref state, (answer.Loaded is null ? 0 : 1) | (answer.HitsInteriorCell is null ? 0 : 2), -1);

        public bool ReportsAll => Volatile.Read(ref state) == 3;

        public FindCellResult Project(FindCellResult guess)
        {
            int known = Volatile.Read(ref state);
            return known < 0
                ? throw new InvalidOperationException("the implementation's optional find_cell fields are not known yet")
                : known == 3 ? guess
                : guess with { Loaded = (known & 1) != 0 ? guess.Loaded : null, HitsInteriorCell = (known & 2) != 0 ? guess.HitsInteriorCell : null };
        }
    }
}
