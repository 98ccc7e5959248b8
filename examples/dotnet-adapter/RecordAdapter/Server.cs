using System.Buffers;
using System.Numerics;
using System.Text;
using System.Text.Encodings.Web;
using System.Text.Json;
using AcPhys.Core;
using AcPhys.Core.Text;

namespace RecordAdapter;

/// <summary>
/// Protocol v1 (docs/protocol.md) for scenes sent as dat records: <c>hello</c>, <c>load_scene</c> with <c>dat</c>,
/// <c>find_cell</c>, <c>find_cell_walk</c>, <c>find_cell_parts_scene</c> and <c>find_cell_parts_transition</c> on a
/// loaded scene, <c>unload_scene</c>. Every request gets one answer line; anything this adapter
/// cannot read is answered <c>{"error": ...}</c> and the next request is served as usual.
/// </summary>
internal sealed class Server
{
    private const int MaxScenes = 16;
    private const string HelloAnswer = """{"protocol":1,"name":"record-adapter (example)","ops":["find_cell_scene","find_cell_transition","load_scene","dat_records","find_cell_walk","find_cell_parts_scene","find_cell_parts_transition","pipeline"],"pick":"retail"}""";
    private static readonly JsonWriterOptions Compact = new() { Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping };

    private readonly Dictionary<string, CellScene> scenes = new(StringComparer.Ordinal);
    private readonly bool partsAnchorOnly;
    private readonly CellArray array = new();
    private int loads;

    /// <summary>Initializes a new instance.</summary>
    /// <exception cref="InputException">A bug name this adapter does not know.</exception>
    /// <param name="bug">
    /// The example's seeded bug (<c>ACPHYS_EXAMPLE_BUG</c>), or null: <c>parts-anchor-only</c> answers a parts query
    /// with the first part alone, a port that drops the rest of the object (e2e/RecordAdapterTests.cs serves it).
    /// </param>
    public Server(string? bug)
    {
        partsAnchorOnly = bug switch
        {
            null or "" => false,
            "parts-anchor-only" => true,
            _ => throw new InputException($"ACPHYS_EXAMPLE_BUG='{bug}' is not a bug of this adapter (known: parts-anchor-only)"),
        };
    }

    /// <summary>Answers one request line.</summary>
    /// <param name="line">The request.</param>
    /// <returns>The answer line (no newline).</returns>
    public string Answer(string line)
    {
        try
        {
            using var doc = JsonDocument.Parse(line);
            var request = doc.RootElement;
            if (request.ValueKind != JsonValueKind.Object)
            {
                return Error("a request must be a JSON object");
            }

            return Text(request, "op") switch
            {
                "hello" => Hello(request),
                "load_scene" => LoadScene(request),
                "find_cell" => FindCell(request),
                "find_cell_walk" => FindCellWalk(request),
                "find_cell_parts_scene" => FindCellParts(request, "find_cell_parts_scene", loadCells: false),
                "find_cell_parts_transition" => FindCellParts(request, "find_cell_parts_transition", loadCells: true),
                "unload_scene" => UnloadScene(request),
                var op => Error($"unknown op \"{op}\""),
            };
        }
        catch (JsonException e)
        {
            return Error("not JSON: " + e.Message);
        }
        catch (InputException e)
        {
            return Error(e.Message);
        }
        catch (Exception e) when (e is not OutOfMemoryException)
        {
            return Error($"internal error: {e.GetType().Name}: {e.Message}");
        }
    }

    private static string Hello(JsonElement request)
    {
        bool ok = !request.TryGetProperty("protocol", out var p) || (p.ValueKind == JsonValueKind.Number && p.TryGetInt32(out int v) && v == 1);
        return ok ? HelloAnswer : Error($"protocol {p.GetRawText()} not supported (this adapter speaks 1)");
    }

    private static string Error(string message) => Line(w => w.WriteString("error", message));

    private static string Line(Action<Utf8JsonWriter> fields)
    {
        var buffer = new ArrayBufferWriter<byte>(256);
        using (var w = new Utf8JsonWriter(buffer, Compact))
        {
            w.WriteStartObject();
            fields(w);
            w.WriteEndObject();
        }

        return Encoding.UTF8.GetString(buffer.WrittenSpan);
    }

    private static string Text(JsonElement obj, string name) =>
        obj.TryGetProperty(name, out var v) && v.ValueKind == JsonValueKind.String ? v.GetString()! : throw new InputException($"field \"{name}\" must be a string");

    private static CellId Cell(JsonElement v, string name) =>
        v.ValueKind == JsonValueKind.String && CellIdText.TryParse(v.GetString(), out var id) ? id : throw new InputException($"field \"{name}\" must be a cell id \"0xAABBCCCC\"");

    // A float32: a JSON number read as double and rounded, or one of the strings "NaN", "Infinity", "-Infinity".
    // at: where the object sits in the request (null: a sphere, a step or the origin).
    internal static float Float(JsonElement s, string name, string? at = null)
    {
        if (s.TryGetProperty(name, out var v))
        {
            if (v.ValueKind == JsonValueKind.Number && v.TryGetDouble(out double d))
            {
                return (float)d;
            }

            if (v.ValueKind == JsonValueKind.String)
            {
                switch (v.GetString())
                {
                    case "NaN":
                        return float.NaN;
                    case "Infinity":
                        return float.PositiveInfinity;
                    case "-Infinity":
                        return float.NegativeInfinity;
                }
            }
        }

        string field = at is null ? $"sphere field \"{name}\"" : $"field \"{at}.{name}\"";
        throw new InputException($"{field} must be a number or \"NaN\" / \"Infinity\" / \"-Infinity\"");
    }

    private string LoadScene(JsonElement request)
    {
        if (!request.TryGetProperty("dat", out var dat))
        {
            return Error("load_scene: this adapter reads scenes as dat records only (field \"dat\": {manifest, records})");
        }

        if (scenes.Count >= MaxScenes)
        {
            return Error($"load_scene: {MaxScenes} scenes already loaded: unload_scene one first");
        }

        CellScene scene;
        try
        {
            scene = SceneLoader.Load(dat);
        }
        catch (InputException e)
        {
            return Error("load_scene: invalid dat records: " + e.Message);
        }

        // pipeline (docs/protocol.md, "Pipelining"): the tool may choose the id, so it can ask before this answer arrives.
        string id = request.TryGetProperty("scene_id", out _) ? Text(request, "scene_id") : "r" + (++loads).ToString(System.Globalization.CultureInfo.InvariantCulture);
        if (!scenes.TryAdd(id, scene))
        {
            return Error($"load_scene: scene_id \"{id}\" is already loaded");
        }

        return Line(w => w.WriteString("scene_id", id));
    }

    private string UnloadScene(JsonElement request)
    {
        string id = Text(request, "scene_id");
        return scenes.Remove(id) ? """{"ok":true}""" : Error($"unload_scene: unknown scene_id \"{id}\"");
    }

    private CellScene LoadedScene(JsonElement request, string op)
    {
        if (!request.TryGetProperty("scene_id", out _))
        {
            throw new InputException($"{op}: this adapter answers loaded scenes only (field \"scene_id\" from load_scene)");
        }

        string id = Text(request, "scene_id");
        return scenes.TryGetValue(id, out var scene) ? scene : throw new InputException($"{op}: unknown scene_id \"{id}\" (load_scene first)");
    }

    private static bool LoadCells(JsonElement request) => request.TryGetProperty("load_cells", out var lc) && lc.ValueKind switch
    {
        JsonValueKind.True => true,
        JsonValueKind.False => false,
        JsonValueKind.Null => false,
        _ => throw new InputException("field \"load_cells\" must be true or false"),
    };

    private static Sphere[] Spheres(JsonElement request, string name)
    {
        if (!request.TryGetProperty(name, out var list) || list.ValueKind != JsonValueKind.Array)
        {
            throw new InputException($"field \"{name}\" must be an array of {{x, y, z, r}}");
        }

        return [.. list.EnumerateArray().Select(s => s.ValueKind == JsonValueKind.Object
            ? new Sphere(new Vector3(Float(s, "x"), Float(s, "y"), Float(s, "z")), Float(s, "r"))
            : throw new InputException($"field \"{name}\" must be an array of {{x, y, z, r}}"))];
    }

    private static CellId Current(JsonElement request) =>
        request.TryGetProperty("current", out var cur) && cur.ValueKind != JsonValueKind.Null ? Cell(cur, "current") : CellId.None;

    private string FindCell(JsonElement request)
    {
        var scene = LoadedScene(request, "find_cell");
        var cell = Cell(request.TryGetProperty("cell", out var c) ? c : default, "cell");
        var current = Current(request);
        bool loadCells = LoadCells(request);
        var spheres = Spheres(request, "spheres");
        return Line(w => Query(w, scene, cell, spheres, current, loadCells));
    }

    // find_cell_walk (docs/protocol.md, "Whole walks"): the walk threaded by the contract's rule, in float32 as a
    // client holds its position: add the move, ask from the frame cell with the body at the position, and on a
    // containing cell re-frame by GetBlockOffset and make it the frame and the current cell.
    private string FindCellWalk(JsonElement request)
    {
        var scene = LoadedScene(request, "find_cell_walk");
        var frame = Cell(request.TryGetProperty("cell", out var c) ? c : default, "cell");
        var current = Current(request);
        bool loadCells = LoadCells(request);
        var body = Spheres(request, "body");
        if (!request.TryGetProperty("origin", out var o) || o.ValueKind != JsonValueKind.Object)
        {
            throw new InputException("field \"origin\" must be an object {x, y, z}");
        }

        var position = new Vector3(Float(o, "x"), Float(o, "y"), Float(o, "z"));
        if (!request.TryGetProperty("steps", out var list) || list.ValueKind != JsonValueKind.Array)
        {
            throw new InputException("field \"steps\" must be an array of {x, y}");
        }

        var moves = list.EnumerateArray().Select(s => s.ValueKind == JsonValueKind.Object
            ? new Vector2(Float(s, "x"), Float(s, "y"))
            : throw new InputException("field \"steps\" must be an array of {x, y}")).ToArray();
        return Line(w =>
        {
            w.WriteStartArray("steps");
            for (int i = 0; i <= moves.Length; i++)
            {
                if (i > 0)
                {
                    position += new Vector3(moves[i - 1].X, moves[i - 1].Y, 0);
                }

                var spheres = body.Select(b => new Sphere(position + b.Center, b.Radius)).ToArray();
                w.WriteStartObject();
                var containing = Query(w, scene, frame, spheres, current, loadCells);
                w.WriteEndObject();
                if (!containing.IsNone)
                {
                    position -= LandDefs.GetBlockOffset(frame, containing);
                    frame = containing;
                    current = containing;
                }
            }

            w.WriteEndArray();
        });
    }

    // find_cell_parts_scene / _transition (docs/protocol.md, "Parts indoors"): the parts cell list of core's
    // ScenePartsQuery over a loaded scene, retail's choices (as ReferenceAdapter); the transition kind runs no
    // visibility filter. There is no containing-cell pick: "containing" is always null.
    private string FindCellParts(JsonElement request, string op, bool loadCells)
    {
        var scene = LoadedScene(request, op);
        var parts = PartsRequest.Read(request);
        if (partsAnchorOnly)
        {
            parts = parts[..1];
        }

        bool hits = ScenePartsQuery.FindCellList(array, scene, parts, loadCells, IndoorFidelity.Retail);
        return Line(w =>
        {
            WriteCells(w);
            w.WriteNull("containing");
            WriteLoaded(w);
            w.WriteBoolean("hits_interior_cell", hits);
        });
    }

    private void WriteCells(Utf8JsonWriter w)
    {
        w.WriteStartArray("cells");
        for (int i = 0; i < array.Count; i++)
        {
            w.WriteStringValue(CellIdText.Format(array[i].Id));
        }

        w.WriteEndArray();
    }

    private void WriteLoaded(Utf8JsonWriter w)
    {
        w.WriteStartArray("loaded");
        for (int i = 0; i < array.Count; i++)
        {
            w.WriteBooleanValue(array[i].Loaded);
        }

        w.WriteEndArray();
    }

    // One find_cell_list, its answer's fields written; returns the containing cell.
    private CellId Query(Utf8JsonWriter w, CellScene scene, CellId cell, Sphere[] spheres, CellId current, bool loadCells)
    {
        // What ReferenceAdapter does for a scene: find_cell_list with the retail pick; load_cells turns the filter off.
        var result = SceneQuery.FindCellList(array, scene, cell, spheres, current, new CellQueryOptions(PickPolicy.Retail, true, loadCells));
        WriteCells(w);
        if (result.Containing.IsNone)
        {
            w.WriteNull("containing");
        }
        else
        {
            w.WriteString("containing", CellIdText.Format(result.Containing));
        }

        WriteLoaded(w);
        w.WriteBoolean("hits_interior_cell", result.HitsInteriorCell);
        return result.Containing;
    }
}
