using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Formats;
using AcPhys.Formats.Scenes;
using AcPhys.Formats.Values;
using AcPhys.Protocol.Child;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Server;

/// <summary>
/// Serves an <see cref="ICellPhysics"/> over protocol v1 (docs/protocol.md): one request per line in, one answer per
/// line out, in order. <c>acphys serve</c> runs it over the reference core so the out-of-process path is tested end to end.
/// </summary>
/// <param name="impl">The implementation to serve.</param>
public sealed class ProtocolServer(ICellPhysics impl)
{
    /// <summary>How many scenes a client may hold loaded at once (it unloads to make room).</summary>
    public const int MaxLoadedScenes = 64;

    /// <summary>The longest scene id a client may choose.</summary>
    public const int MaxSceneIdLength = 64;

    private readonly Dictionary<string, Scene> loadedScenes = [];
    private int nextSceneId;

    // The last scene read, by its exact text: a walk sends the same scene on every step, and reusing the instance
    // reuses its built core scene (SceneBuild caches per instance).
    // One reference, swapped whole, so concurrent Answer calls never see a text paired with another scene.
    private LastScene? last;

    /// <summary>Gets or initializes a value indicating whether the server announces <c>load_scene</c> (true by default; false serves as an older server would).</summary>
    public bool LoadScenes { get; init; } = true;

    /// <summary>Gets or initializes a value indicating whether the server announces <c>dat_records</c> with <c>load_scene</c> (true by default: scenes then arrive as dat records).</summary>
    public bool DatRecords { get; init; } = true;

    /// <summary>Gets or initializes a value indicating whether the server announces <c>find_cell_walk</c> and <c>find_cell_parts_walk</c> (true by default; false serves as an older server would: walks come query by query).</summary>
    public bool Walks { get; init; } = true;

    /// <summary>Gets or initializes a value indicating whether the server declares <c>"frame": "world"</c> and converts each request's world coordinates back to block frames, as a world-frame port's shim would (<see cref="WorldFrame"/>).</summary>
    public bool InWorldFrame { get; init; }

    /// <summary>Gets or initializes a value indicating whether the server announces <c>pipeline</c> (true by default; false serves as an older server would: it chooses every scene id itself).</summary>
    public bool Pipeline { get; init; } = true;

    /// <summary>Reads requests until end of input, answering each on its own line.</summary>
    /// <param name="input">Requests, UTF-8 lines.</param>
    /// <param name="output">Answers (flushed whenever no further request is waiting in the input buffer).</param>
    /// <param name="maxLineBytes">The most bytes of one request line (<see cref="LineLimit"/>); a longer one gets an error answer naming the limit and is skipped unread.</param>
    public void Serve(Stream input, TextWriter output, int maxLineBytes = BoundedLineReader.DefaultMaxBytes)
    {
        var reader = new BoundedLineReader(input, maxLineBytes);
        while (true)
        {
            if (!reader.HasBufferedLine)
            {
                long f = WireProfile.Start();
                output.Flush(); // before any wait for input; a pipelining client's requests already here are answered first, together
                WireProfile.Stop("child: flush", f);
            }

            string answer;
            try
            {
                if (reader.ReadLineUtf8() is not { } line)
                {
                    output.Flush();
                    return;
                }

                if (line.Length == 0)
                {
                    continue;
                }

                long t = WireProfile.Start();
                answer = Answer(line);
                WireProfile.Stop("child: answer (all ops)", t);
            }
            catch (LineTooLongException e)
            {
                answer = Error("malformed request: " + e.Message);
            }

            output.WriteLine(answer);
        }
    }

    /// <summary>Answers one request line.</summary>
    /// <param name="line">The request.</param>
    /// <returns>The answer line: the op's result or <c>{"error": ...}</c>.</returns>
    public string Answer(string line) => Guarded(() => AnswerChecked(line));

    /// <summary>Answers one request line given as its UTF-8 bytes, exactly as <see cref="Answer(string)"/> answers the line's text.</summary>
    /// <param name="line">The request's bytes (invalid UTF-8 is read as the text it decodes to, U+FFFD for each bad sequence).</param>
    /// <returns>The answer line.</returns>
    /// <remarks>Issue 26: a valid UTF-8 request is parsed from its bytes (a 13 KB scene load was decoded into a string and
    /// encoded back for the parser); any other, and every request of a world-frame server, goes through its text.</remarks>
    public string Answer(ReadOnlyMemory<byte> line) => Guarded(() => AnswerChecked(line));

    /// <summary>Answers one request line given as its UTF-8 bytes, as <see cref="AnswerChecked(string)"/> answers its text (a server bug escapes).</summary>
    /// <param name="line">The request's bytes.</param>
    /// <returns>The answer line.</returns>
    public string AnswerChecked(ReadOnlyMemory<byte> line)
    {
        return InWorldFrame || !System.Text.Unicode.Utf8.IsValid(line.Span)
            ? AnswerChecked(System.Text.Encoding.UTF8.GetString(line.Span))
            : Dispatched(() => Wire.Parse(line));
    }

    /// <summary>Answers one request line; a request it cannot serve gets an <c>{"error": ...}</c> answer.</summary>
    /// <param name="line">The request.</param>
    /// <returns>The answer line.</returns>
    /// <remarks><para>
    /// Every defect of the request (not JSON, not an object, a missing or mistyped field, an invalid scene or dat
    /// record) is answered as an error. Any exception that escapes is a bug of the server: <see cref="Answer(string)"/> turns it
    /// into an "internal error" answer, and the <c>serve-request</c> fuzz target reports it as a crash.
    /// </para></remarks>
    public string AnswerChecked(string line) => Dispatched(() => Wire.Parse(InWorldFrame ? WorldFrame.ToBlock(line) : line));

    // A bug of this server, not of the request: AnswerChecked lets it escape so the serve-request fuzz target sees it.
    private static string Guarded(Func<string> answer)
    {
        try
        {
            return answer();
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return Error($"internal error ({e.GetType().Name}): {Wire.Brief(e.Message, 200)}");
        }
    }

    // The request parsed and dispatched; a request that is not protocol v1 (or a malformed field) gets an error answer.
    private string Dispatched(Func<JsonDocument> parse)
    {
        try
        {
            using var doc = parse();
            return Dispatch(doc.RootElement);
        }
        catch (WireException e)
        {
            return Error("malformed request: " + e.Message);
        }
    }

    private static string Error(string message) => Answers.Error.Line(message);

    // Dispatch from the tables: the queries without a scene are rows of MessageTable; the requests about scenes and
    // the handshake are this server's, since it holds the scenes.
    private string Dispatch(JsonElement request)
    {
        string op = Wire.ReadString(request, "op");
        switch (op)
        {
            case "hello":
                return Hello(request);
            case "load_scene":
                return WireProfile.Time("child: load_scene", () => LoadScene(request));
            case "unload_scene":
                return UnloadScene(request);
            case "find_cell_walk":
                return InWorldFrame
                    ? Error("find_cell_walk is not offered in the world frame (walks are asked query by query)")
                    : WireProfile.Time("child: find_cell_walk", () => FindCellWalk(request));
            case "find_cell" or "find_cell_scene": // find_cell_scene is announced, never sent: a scene travels in find_cell (docs/protocol.md, "Scenes")
                return FindCell(request);
            case "find_cell_parts_walk":
                return InWorldFrame
                    ? Error("find_cell_parts_walk is not offered in the world frame (parts queries are asked one by one)")
                    : WireProfile.Time("child: find_cell_parts_walk", () => FindCellPartsWalk(request));
            case "find_cell_parts_scene":
                return FindCellParts(request, MessageTable.FindCellPartsScene);
            case "find_cell_parts_transition":
                return FindCellParts(request, MessageTable.FindCellPartsTransition);
        }

        if (MessageTable.ByName.TryGetValue(op, out var message))
        {
            return (impl.Ops & message.Op) == 0 ? Error($"op \"{op}\" not offered by {impl.Name}") : message.Serve(impl, request);
        }

        // An op or capability name that is not a query this server answers: refused as not offered when the
        // implementation lacks it, else unknown.
        var known = CapabilityNames.Parse([op], out var capability, out _);
        return (known != Op.None && (impl.Ops & known) == 0) || capability != Capability.None
            ? Error($"op \"{op}\" not offered by {impl.Name}")
            : Error($"unknown op \"{Wire.Brief(op, 64)}\"");
    }

    private string UnloadScene(JsonElement request)
    {
        string id = Wire.ReadString(request, "scene_id");
        lock (loadedScenes)
        {
            return loadedScenes.Remove(id) ? Answers.Ok.Line(true) : Error($"unknown scene_id \"{Wire.Brief(id, 40)}\"");
        }
    }

    // find_cell: open land (with its origin), a scene's static placement, or a transition (load_cells).
    private string FindCell(JsonElement request)
    {
        if (SceneOf(request, "find_cell", out var scene) is string refused)
        {
            return refused;
        }

        bool loadCells = request.TryGetProperty("load_cells", out _) && Wire.ReadBool(request, "load_cells");
        if (loadCells && (impl.Ops & Op.FindCellTransition) == 0)
        {
            return Error($"transition queries (load_cells) not served by {impl.Name} (it does not offer find_cell_transition)");
        }

        if (StaticRefused(scene, loadCells) is string noStatic)
        {
            return noStatic;
        }

        var r = scene is null && !loadCells
            ? impl.FindCell(Wire.ReadCell(request, "cell"), Wire.ReadOrigin(request), Wire.ReadSpheres(request, "spheres"), Wire.ReadOptionalCell(request, "current"))
            : impl.FindCell(scene, Wire.ReadCell(request, "cell"), Wire.ReadSpheres(request, "spheres"), Wire.ReadOptionalCell(request, "current"), loadCells);
        return Answers.FindCell.Line(r);
    }

    // find_cell_parts_scene / _transition: the scene as find_cell's (scene_id or inline; never open land), then the row.
    private string FindCellParts(JsonElement request, Message<PartsInScene, FindCellResult> row)
    {
        if ((impl.Ops & row.Op) == 0)
        {
            return Error($"op \"{row.Name}\" not offered by {impl.Name}");
        }

        var sceneField = request.TryGetProperty("scene_id", out _) ? default : Wire.Field(request, "scene");
        if (sceneField.ValueKind == JsonValueKind.Null)
        {
            return Error($"{row.Name} needs a scene (\"scene_id\" or \"scene\"): the parts variant indoors has no open-land form (outside_cells_parts is)");
        }

        if (ScenePartsOf(request, out var scene) is string refused)
        {
            return refused;
        }

        return row.Answer.Line(row.Ask(impl, row.ReadRequest(request) with { Scene = scene }));
    }

    // find_cell_parts_walk: one walk's parts queries of one kind, answered by the implementation's walk (its array, under
    // ace-keeps-stale-cells, lives for the walk: facts §7 #6), one answer per query.
    private string FindCellPartsWalk(JsonElement request)
    {
        var queries = PartsWalkWire.ReadFields(request, out bool loadCells);
        var row = loadCells ? MessageTable.FindCellPartsTransition : MessageTable.FindCellPartsScene;
        if ((impl.Ops & row.Op) == 0)
        {
            return Error($"find_cell_parts_walk{(loadCells ? " (load_cells)" : string.Empty)} needs {row.Name}, which {impl.Name} does not offer");
        }

        var sceneField = request.TryGetProperty("scene_id", out _) ? default : Wire.Field(request, "scene");
        if (sceneField.ValueKind == JsonValueKind.Null)
        {
            return Error("find_cell_parts_walk needs a scene (\"scene_id\" or \"scene\"): the parts variant indoors has no open-land form");
        }

        if (ScenePartsOf(request, out var scene) is string refused)
        {
            return refused;
        }

        var answers = impl.FindCellPartsWalk(scene!, queries, loadCells);
        return Answers.Walk(answers.Count).Line(answers);
    }

    // The scene of a parts request: loaded by id, or inline (read whatever scene queries the implementation offers).
    private string? ScenePartsOf(JsonElement request, out Scene? scene)
    {
        scene = null;
        if (request.TryGetProperty("scene_id", out _))
        {
            string id = Wire.ReadString(request, "scene_id");
            lock (loadedScenes)
            {
                return loadedScenes.TryGetValue(id, out scene) ? null : Error($"unknown scene_id \"{Wire.Brief(id, 40)}\" (load_scene first)");
            }
        }

        scene = ReadScene(Wire.Field(request, "scene"));
        return null;
    }

    // find_cell_walk: the walk threaded here by the rule the tool's runners use (WalkThread), one answer per query.
    private string FindCellWalk(JsonElement request)
    {
        if (SceneOf(request, "find_cell_walk", out var scene) is string refused)
        {
            return refused;
        }

        var walk = WalkWire.ReadFields(request, scene);
        if (walk.LoadCells && (impl.Ops & Op.FindCellTransition) == 0)
        {
            return Error($"transition queries (load_cells) not served by {impl.Name} (it does not offer find_cell_transition)");
        }

        if (StaticRefused(scene, walk.LoadCells) is string noStatic)
        {
            return noStatic;
        }

        var answers = impl.FindCellWalk(walk);
        return Answers.Walk(answers.Count).Line(answers);
    }

    // A scene query asked as static placement of an implementation that offers only the transition kind (issue #29).
    private string? StaticRefused(Scene? scene, bool loadCells) =>
        scene is not null && !loadCells && (impl.Ops & Op.FindCellScene) == 0
            ? Error($"static placement (find_cell_scene) not offered by {impl.Name}: it answers scenes only as transitions (load_cells true)")
            : null;

    // The scene a find_cell or find_cell_walk request names: scene_id (loaded), an inline scene, or null (open land).
    // Returns the error answer when the request cannot be served, else null.
    private string? SceneOf(JsonElement request, string op, out Scene? scene)
    {
        scene = null;
        var sceneField = request.TryGetProperty("scene_id", out var sceneId) ? default : Wire.Field(request, "scene");
        if (sceneId.ValueKind != JsonValueKind.Undefined)
        {
            string id = Wire.ReadString(request, "scene_id");
            lock (loadedScenes)
            {
                if (!loadedScenes.TryGetValue(id, out scene))
                {
                    return Error($"unknown scene_id \"{Wire.Brief(id, 40)}\" (load_scene first)");
                }
            }
        }
        else if (sceneField.ValueKind != JsonValueKind.Null)
        {
            if (!SceneQueryKinds.OffersScenes(impl.Ops))
            {
                return Error($"scenes not served by {impl.Name} (it offers neither find_cell_scene nor find_cell_transition)");
            }

            scene = ReadScene(sceneField);
        }
        else if ((impl.Ops & Op.FindCell) == 0)
        {
            return Error($"op \"{op}\" on open land not offered by {impl.Name}");
        }

        return null;
    }

    private string LoadScene(JsonElement request)
    {
        if (!SceneQueryKinds.OffersScenes(impl.Ops))
        {
            return Error($"scenes not served by {impl.Name} (it offers neither find_cell_scene nor find_cell_transition)");
        }

        // A pipelining client names the scene itself (docs/protocol.md, "Pipelining"); an older server ignores the field.
        string? chosen = Pipeline && request.TryGetProperty("scene_id", out _) ? ChosenId(request) : null;
        var scene = request.TryGetProperty("dat", out var dat) ? DatWire.ReadScene(dat) : ReadScene(Wire.Field(request, "scene"));
        lock (loadedScenes)
        {
            if (loadedScenes.Count >= MaxLoadedScenes)
            {
                return Error($"{MaxLoadedScenes} scenes already loaded: unload_scene one first");
            }

            string id = chosen ?? "s" + (++nextSceneId).ToString(System.Globalization.CultureInfo.InvariantCulture);
            if (loadedScenes.ContainsKey(id))
            {
                return Error($"scene_id \"{Wire.Brief(id, 40)}\" is already loaded: unload_scene it first");
            }

            loadedScenes[id] = scene;
            if (WireProfile.On)
            {
                WireProfile.Time("child: SceneBuild.Build (eager when profiled)", () => SceneBuild.Build(scene));
            }

            return Answers.SceneId.Line(id);
        }
    }

    private static string ChosenId(JsonElement request)
    {
        string id = Wire.ReadString(request, "scene_id");
        return id.Length is > 0 and <= MaxSceneIdLength
            ? id
            : throw new WireException($"field \"scene_id\": 1 to {MaxSceneIdLength} characters, got {id.Length}");
    }

    private Scene ReadScene(JsonElement field)
    {
        string text = field.GetRawText();
        if (last is { } hit && hit.Text == text)
        {
            return hit.Scene;
        }

        try
        {
            var scene = SceneJson.Read(field, "find_cell", "$.scene");
            last = new LastScene(text, scene);
            return scene;
        }
        catch (InputFormatException e)
        {
            throw new WireException("invalid scene: " + e.Message, e);
        }
    }

    private string Hello(JsonElement request)
    {
        if (request.TryGetProperty("protocol", out var p) && !(p.ValueKind == JsonValueKind.Number && p.TryGetInt32(out int v) && v == Wire.Version))
        {
            return Error($"protocol {Wire.Show(p)} not supported (this server speaks {Wire.Version})");
        }

        return Wire.Line(w =>
        {
            w.WriteNumber("protocol", Wire.Version);
            w.WriteString("name", impl.Name);
            w.WriteStartArray("ops");
            var ops = impl.Ops;
            var capabilities = Pipeline ? Capability.Pipeline : Capability.None; // answers depend on the request alone; scene ids may be the client's
            capabilities |= Walks && !InWorldFrame && (ops & (Op.FindCell | SceneQueryKinds.Either)) != 0 ? Capability.FindCellWalk : Capability.None; // threaded here (WalkThread)
            capabilities |= Walks && !InWorldFrame && (ops & (Op.FindCellPartsScene | Op.FindCellPartsTransition)) != 0 ? Capability.FindCellPartsWalk : Capability.None;
            if (LoadScenes && SceneQueryKinds.OffersScenes(ops))
            {
                capabilities |= Capability.LoadScene; // the server holds the scenes; the implementation behind it needs nothing for it
                capabilities |= DatRecords ? Capability.DatRecords : Capability.None; // and reads them from records with the project's reader
            }

            foreach (var name in OpNames.Names(ops).Concat(CapabilityNames.Names(capabilities)))
            {
                w.WriteStringValue(name);
            }

            w.WriteEndArray();
            w.WriteString("pick", PickNames.Of(impl.Pick));
            if (InWorldFrame)
            {
                w.WriteString("frame", WorldFrame.Name);
            }

            var fidelity = FidelityNames.Names(impl.Indoor, impl.Outdoor);
            if (fidelity.Count > 0)
            {
                w.WriteStartArray("fidelity");
                foreach (var name in fidelity)
                {
                    w.WriteStringValue(name);
                }

                w.WriteEndArray();
            }
        });
    }

    private sealed record LastScene(string Text, Scene Scene);
}
