using System.Globalization;
using System.Numerics;
using System.Text.Json;
using AcPhys.Core;

namespace RecordAdapter;

/// <summary>
/// The port's glue: the <c>dat</c> object of <c>load_scene</c> (a record folder's manifest and its records in base64)
/// turned into the core's <see cref="CellScene"/>. Loaded blocks, unloaded cells and visible cells of other blocks
/// come from the manifest (records cannot hold them); everything else from the records: each EnvCell with its
/// CellStruct's cell BSP as a <see cref="BspVolume"/> and its portal planes computed from the portal polygons'
/// vertices; each LandblockInfo's buildings.
/// </summary>
internal static class SceneLoader
{
    private enum RecordType
    {
        EnvCell,
        Environment,
        LandblockInfo,
        Landblock,
    }

    /// <summary>Builds the scene.</summary>
    /// <param name="dat">The <c>dat</c> object: <c>{"manifest": {...}, "records": {"XXXXXXXX.bin": "base64", ...}}</c>.</param>
    /// <returns>The scene.</returns>
    /// <exception cref="InputException">The manifest or a record is malformed, or they do not fit together.</exception>
    public static CellScene Load(JsonElement dat)
    {
        Expect(dat.ValueKind == JsonValueKind.Object, "dat: expected an object {\"manifest\", \"records\"}");
        var bytes = RecordBytes(Field(dat, "records", "dat"));
        var manifest = Field(dat, "manifest", "dat");
        const string m = "dat.manifest";
        Expect(manifest.ValueKind == JsonValueKind.Object, m + ": expected an object");
        Expect(Text(Field(manifest, "format", m), m + ".format") == "acphys-dat-scene", m + ".format: expected \"acphys-dat-scene\"");
        Expect(Field(manifest, "version", m) is { ValueKind: JsonValueKind.Number } v && v.TryGetInt32(out int version) && version == 1, m + ".version: expected 1");
        var records = Records(manifest, bytes);
        var blocks = Items(manifest, "blocks", m).Select((e, i) => Block(e, $"{m}.blocks[{i}]")).ToHashSet();
        _ = Items(manifest, "unloadedBlocks", m).Select((e, i) => Block(e, $"{m}.unloadedBlocks[{i}]")).ToList();
        var unloadedCells = Items(manifest, "unloadedCells", m).Select((e, i) => Cell(e, $"{m}.unloadedCells[{i}]")).ToHashSet();
        var elsewhere = new Dictionary<CellId, CellId[]>();
        var listed = Items(manifest, "visibleElsewhere", m);
        for (int i = 0; i < listed.Count; i++)
        {
            string at = $"{m}.visibleElsewhere[{i}]";
            var cell = Cell(Field(listed[i], "cell", at), at + ".cell");
            Expect(elsewhere.TryAdd(cell, [.. Items(listed[i], "visible", at).Select((e, k) => Cell(e, $"{at}.visible[{k}]"))]), $"{at}.cell: {cell} is listed twice");
        }

        var environments = new Dictionary<uint, Dictionary<uint, CellStructRecord>>();
        var landblocks = new HashSet<LandblockId>();
        var numCells = new Dictionary<LandblockId, uint>();
        var buildingsOf = new Dictionary<LandblockId, List<Building>>();
        var withObjects = new HashSet<LandblockId>();
        foreach (var (id, type, data) in records)
        {
            var block = new LandblockId((ushort)(id >> 16));
            switch (type)
            {
                case RecordType.Environment:
                    environments[id] = RecordReader.Environment(data, id);
                    break;
                case RecordType.Landblock:
                    if (RecordReader.Landblock(data, id))
                    {
                        withObjects.Add(block);
                    }

                    landblocks.Add(block);
                    break;
                case RecordType.LandblockInfo:
                    var (count, list) = RecordReader.LandblockInfo(data, id);
                    numCells[block] = count;
                    buildingsOf[block] = [.. list.Select(b => new Building(block, b.Frame.Origin, b.Portals))];
                    break;
            }
        }

        // As ACE: a loaded block's buildings are read only when its Landblock record says hasObjects 1.
        var buildings = buildingsOf.Where(kv => !landblocks.Contains(kv.Key) || withObjects.Contains(kv.Key)).SelectMany(kv => kv.Value).ToList();

        Expect(landblocks.SetEquals(blocks), $"{m}.blocks: the loaded blocks ({string.Join(", ", blocks)}) are not those with a Landblock record ({string.Join(", ", landblocks)})");
        var cells = new List<EnvCell>();
        foreach (var (id, type, data) in records)
        {
            var cell = new CellId(id);
            if (type == RecordType.EnvCell && !unloadedCells.Contains(cell))
            {
                Expect(numCells.TryGetValue(cell.Landblock, out uint n) && cell.Low < LandDefs.FirstEnvCellId + n, $"EnvCell {cell}: beyond the numCells of LandblockInfo 0x{cell.Landblock.Value:X4}FFFE (or there is none)");
                cells.Add(EnvCell(cell, RecordReader.EnvCell(data, id), environments, elsewhere.GetValueOrDefault(cell) ?? []));
            }
        }

        foreach (var cell in elsewhere.Keys)
        {
            Expect(cells.Any(c => c.Id == cell), $"{m}.visibleElsewhere: {cell} has no loaded EnvCell record");
        }

        try
        {
            return new CellScene(blocks, cells, buildings);
        }
        catch (ArgumentException e)
        {
            throw new InputException("the records describe no valid scene: " + e.Message);
        }
    }

    private static EnvCell EnvCell(CellId id, EnvCellRecord r, Dictionary<uint, Dictionary<uint, CellStructRecord>> environments, CellId[] elsewhere)
    {
        string where = $"EnvCell {id}";
        uint environment = 0x0D000000u | r.EnvironmentId;
        Expect(environments.TryGetValue(environment, out var structs), $"{where}: environmentId at byte {r.EnvironmentAt}: Environment 0x{environment:X8} was not sent");
        Expect(structs!.TryGetValue(r.CellStructure, out var cs), $"{where}: cellStructure at byte {r.EnvironmentAt + 2}: Environment 0x{environment:X8} has no CellStruct {r.CellStructure}");
        var portals = new CellPortal[r.Portals.Length];
        for (int i = 0; i < portals.Length; i++)
        {
            var p = r.Portals[i];
            string field = $"{where}: portals[{i}].polygonId at byte {r.PortalsAt + (8 * i) + 2}: polygon {p.PolygonId} of CellStruct {r.CellStructure}";
            portals[i] = new CellPortal(p.Flags, p.PolygonId, p.OtherCellId, p.OtherPortalId, PolygonPlane(cs!, p.PolygonId, field));
        }

        CellId[] visible = [.. r.Visible.Select(id.WithLow), .. elsewhere];
        return new EnvCell(id, r.Frame, new BspVolume(cs!.CellBsp, FaceBounds(cs)), portals, visible);
    }

    // The plane of a polygon from its vertices: the fan sum of (vᵢ − v₀) × (vᵢ₊₁ − v₀), normalised; d = −N·v₀.
    private static CellPlane PolygonPlane(CellStructRecord cs, ushort polygonId, string field)
    {
        Expect(cs.Polygons.TryGetValue(polygonId, out var ids), field + ": no such polygon");
        Expect(ids!.Length >= 3, $"{field}: {ids.Length} vertices, a plane needs 3");
        var points = new Vector3[ids.Length];
        for (int i = 0; i < ids.Length; i++)
        {
            Expect(cs.Vertices.TryGetValue(ids[i], out points[i]), $"{field}: names vertex {ids[i]}, which the CellStruct lacks");
        }

        var sum = Vector3.Zero;
        for (int i = 1; i + 1 < points.Length; i++)
        {
            sum += Vector3.Cross(points[i] - points[0], points[i + 1] - points[0]);
        }

        float length = sum.Length();
        Expect(length > 1e-12f && float.IsFinite(length), field + ": spans no area");
        var n = sum / length;
        return new CellPlane(n, -Vector3.Dot(n, points[0]));
    }

    // The bounds of the vertices of the cell's own faces (portal polygons extend past the cell; they are left out).
    private static Box FaceBounds(CellStructRecord cs)
    {
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        foreach (var (id, ids) in cs.Polygons)
        {
            if (Array.IndexOf(cs.PortalPolygons, id) >= 0)
            {
                continue;
            }

            foreach (ushort v in ids)
            {
                if (cs.Vertices.TryGetValue(v, out var p))
                {
                    min = Vector3.Min(min, p);
                    max = Vector3.Max(max, p);
                }
            }
        }

        return min.X <= max.X ? new Box(min, max) : new Box(Vector3.Zero, Vector3.Zero);
    }

    private static Dictionary<string, byte[]> RecordBytes(JsonElement records)
    {
        Expect(records.ValueKind == JsonValueKind.Object, "dat.records: expected an object mapping record file names to base64");
        var bytes = new Dictionary<string, byte[]>(StringComparer.Ordinal);
        foreach (var p in records.EnumerateObject())
        {
            byte[]? data = null;
            Expect(p.Value.ValueKind == JsonValueKind.String && p.Value.TryGetBytesFromBase64(out data), $"dat.records[\"{p.Name}\"]: not a base64 string");
            Expect(bytes.TryAdd(p.Name, data!), $"dat.records[\"{p.Name}\"]: sent twice");
        }

        return bytes;
    }

    // The manifest's records list, in reading order, with each record's bytes; ids must name their type and dat.
    private static List<(uint Id, RecordType Type, byte[] Data)> Records(JsonElement manifest, Dictionary<string, byte[]> bytes)
    {
        var result = new List<(uint, RecordType, byte[])>();
        var files = new HashSet<string>(StringComparer.Ordinal);
        var items = Items(manifest, "records", "dat.manifest");
        for (int i = 0; i < items.Count; i++)
        {
            string at = $"dat.manifest.records[{i}]";
            uint id = Hex(Field(items[i], "id", at), at + ".id", 8);
            bool portal = Text(Field(items[i], "dat", at), at + ".dat") switch
            {
                "portal" => true,
                "cell" => false,
                _ => throw new InputException(at + ".dat: expected \"cell\" or \"portal\""),
            };
            string typeName = Text(Field(items[i], "type", at), at + ".type");
            Expect(Enum.TryParse<RecordType>(typeName, out var type) && type.ToString() == typeName, $"{at}.type: \"{typeName}\" is none of {string.Join(", ", Enum.GetNames<RecordType>())}");
            ushort low = (ushort)id;
            bool fits = type switch
            {
                RecordType.Environment => portal && id >> 24 == 0x0D,
                RecordType.Landblock => !portal && low == 0xFFFF,
                RecordType.LandblockInfo => !portal && low == 0xFFFE,
                _ => !portal && low is >= LandDefs.FirstEnvCellId and <= LandDefs.LastEnvCellId,
            };
            Expect(fits, $"{at}: id 0x{id:X8} in the {(portal ? "portal" : "cell")} dat is no {type}");
            string file = id.ToString("X8", CultureInfo.InvariantCulture) + ".bin";
            Expect(Text(Field(items[i], "file", at), at + ".file") == file, $"{at}.file: expected \"{file}\"");
            Expect(files.Add(file), $"{at}.file: {file} is listed twice");
            Expect(bytes.TryGetValue(file, out var data), $"dat.records: {file} ({type} 0x{id:X8}) is listed in the manifest but not sent");
            result.Add((id, type, data!));
        }

        var extra = bytes.Keys.FirstOrDefault(k => !files.Contains(k));
        Expect(extra is null, $"dat.records[\"{extra}\"]: not listed in the manifest");
        return result;
    }

    private static LandblockId Block(JsonElement e, string at) => new((ushort)Hex(e, at, 4));

    private static CellId Cell(JsonElement e, string at) => new(Hex(e, at, 8));

    private static uint Hex(JsonElement e, string at, int digits)
    {
        string text = Text(e, at);
        uint value = 0;
        bool ok = text.Length == digits + 2 && text.StartsWith("0x", StringComparison.Ordinal)
            && uint.TryParse(text.AsSpan(2), NumberStyles.AllowHexSpecifier, CultureInfo.InvariantCulture, out value);
        Expect(ok, $"{at}: expected \"0x\" and {digits} hex digits, got \"{text}\"");
        return value;
    }

    private static JsonElement Field(JsonElement obj, string name, string at) =>
        obj.ValueKind == JsonValueKind.Object && obj.TryGetProperty(name, out var v) ? v : throw new InputException($"{at}.{name}: missing");

    private static string Text(JsonElement e, string at) =>
        e.ValueKind == JsonValueKind.String ? e.GetString()! : throw new InputException(at + ": expected a string");

    private static List<JsonElement> Items(JsonElement obj, string name, string at)
    {
        var e = Field(obj, name, at);
        Expect(e.ValueKind == JsonValueKind.Array, $"{at}.{name}: expected an array");
        return [.. e.EnumerateArray()];
    }

    private static void Expect(bool ok, string message)
    {
        if (!ok)
        {
            throw new InputException(message);
        }
    }
}
