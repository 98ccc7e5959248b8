using System.Buffers.Binary;
using System.Numerics;
using AcPhys.Core;

namespace RecordAdapter;

/// <summary>Input this adapter cannot use: a malformed request, manifest or record (a record's message names the field and its byte offset).</summary>
/// <param name="message">The message.</param>
internal sealed class InputException(string message) : Exception(message);

/// <summary>An EnvCell portal as stored: flags, the portal polygon, the cell behind (low word) and its portal index.</summary>
/// <param name="Flags">1 ExactMatch, 2 clear ⇒ PortalSide, 4 outside.</param>
/// <param name="PolygonId">A polygon of the cell's CellStruct.</param>
/// <param name="OtherCellId">Low word of the cell behind; 0xFFFF outside.</param>
/// <param name="OtherPortalId">Index into that cell's portals; 0xFFFF none.</param>
internal readonly record struct PortalRecord(ushort Flags, ushort PolygonId, ushort OtherCellId, ushort OtherPortalId);

/// <summary>The fields of an EnvCell record that membership needs.</summary>
/// <param name="EnvironmentId">Low word of the Environment record (0x0D00xxxx).</param>
/// <param name="CellStructure">The CellStruct key in that Environment.</param>
/// <param name="Frame">The cell's frame in its block.</param>
/// <param name="Portals">Portals in dat order.</param>
/// <param name="Visible">Low words of the visible cells of the same block.</param>
/// <param name="EnvironmentAt">The byte offset of the environment id (the CellStruct key follows it).</param>
/// <param name="PortalsAt">The byte offset of the portal list (8 bytes a portal, the polygon id at +2).</param>
internal sealed record EnvCellRecord(ushort EnvironmentId, ushort CellStructure, Frame Frame, PortalRecord[] Portals, ushort[] Visible, int EnvironmentAt, int PortalsAt);

/// <summary>The parts of a CellStruct membership needs: vertices, polygons (as vertex ids), portal polygon ids, the cell BSP.</summary>
/// <param name="Vertices">Vertex positions by id.</param>
/// <param name="Polygons">Vertex ids by polygon id.</param>
/// <param name="PortalPolygons">The portal polygon ids.</param>
/// <param name="CellBsp">The cell BSP nodes; index 0 is the root.</param>
internal sealed record CellStructRecord(Dictionary<ushort, Vector3> Vertices, Dictionary<ushort, ushort[]> Polygons, ushort[] PortalPolygons, BspNode[] CellBsp);

/// <summary>A building of a LandblockInfo: its frame and its portals.</summary>
/// <param name="Frame">The frame in the block.</param>
/// <param name="Portals">Building portals in dat order.</param>
internal sealed record BuildingRecord(Frame Frame, BldPortal[] Portals);

/// <summary>
/// A bounded little-endian reader for one record, and the layouts of the four record types a scene uses
/// (EnvCell, Environment, LandblockInfo, Landblock). Every count is checked against the bytes left before anything is
/// allocated; every failure is a <see cref="InputException"/> naming the record, the field and its byte offset.
/// </summary>
internal sealed class RecordReader
{
    private const int MaxTreeDepth = 256;
    private static readonly uint Leaf = Tag("LEAF"), Port = Tag("PORT");
    private static readonly uint[] PositiveOnly = [Tag("BPnn"), Tag("BPIn")], NegativeOnly = [Tag("BpIN"), Tag("BpnN")], Both = [Tag("BPIN"), Tag("BPnN")];

    private readonly byte[] data;
    private readonly string record;
    private int pos;

    private RecordReader(byte[] data, string record)
    {
        this.data = data;
        this.record = record;
    }

    private enum Tree
    {
        Cell,
        Physics,
        Drawing,
    }

    /// <summary>Reads an EnvCell record.</summary>
    /// <param name="bytes">The record.</param>
    /// <param name="id">Its id.</param>
    /// <returns>The fields membership needs.</returns>
    public static EnvCellRecord EnvCell(byte[] bytes, uint id)
    {
        var r = new RecordReader(bytes, $"EnvCell 0x{id:X8}");
        r.Id(id);
        int flagsAt = r.pos;
        uint flags = r.U32("flags");
        r.Check((flags & ~0xBu) == 0, "flags", flagsAt, $"unknown bits 0x{flags & ~0xBu:X} (known: 1, 2, 8)");
        r.Skip(4, "cell id (again)");
        int numSurfaces = r.U8("numSurfaces");
        int numPortals = r.U8("numPortals");
        int numVisible = r.U16("numStabs");
        r.Count((2 * numSurfaces) + 32 + (8 * numPortals) + (2 * numVisible), 1, "numSurfaces/numPortals/numStabs", 12);
        r.Skip(2 * numSurfaces, "surfaces");
        int environmentAt = r.pos;
        ushort environment = r.U16("environmentId");
        ushort cellStructure = r.U16("cellStructure");
        var frame = r.Frame("position");
        int portalsAt = r.pos;
        var portals = new PortalRecord[numPortals];
        for (int i = 0; i < numPortals; i++)
        {
            string f = $"portals[{i}]";
            portals[i] = new PortalRecord(r.U16(f + ".flags"), r.U16(f + ".polygonId"), r.U16(f + ".otherCellId"), r.U16(f + ".otherPortalId"));
        }

        var visible = new ushort[numVisible];
        for (int i = 0; i < numVisible; i++)
        {
            visible[i] = r.U16($"visibleCells[{i}]");
        }

        if ((flags & 2) != 0)
        {
            int at = r.pos;
            r.Skip(32 * r.Count(r.U32("staticObjects.count"), 32, "staticObjects.count", at), "staticObjects");
        }

        if ((flags & 8) != 0)
        {
            r.Skip(4, "restrictionObject");
        }

        r.End();
        return new EnvCellRecord(environment, cellStructure, frame, portals, visible, environmentAt, portalsAt);
    }

    /// <summary>Reads an Environment record.</summary>
    /// <param name="bytes">The record.</param>
    /// <param name="id">Its id.</param>
    /// <returns>The CellStructs by key.</returns>
    public static Dictionary<uint, CellStructRecord> Environment(byte[] bytes, uint id)
    {
        var r = new RecordReader(bytes, $"Environment 0x{id:X8}");
        r.Id(id);
        int count = r.Count(r.U32("numCellStructs"), 28, "numCellStructs", 4);
        var structs = new Dictionary<uint, CellStructRecord>();
        for (int i = 0; i < count; i++)
        {
            int at = r.pos;
            uint key = r.U32($"cellStructs[{i}].key");
            r.Check(structs.TryAdd(key, r.CellStruct($"cellStructs[{i}]")), $"cellStructs[{i}].key", at, $"duplicate key {key}");
        }

        r.End();
        return structs;
    }

    /// <summary>Reads a LandblockInfo record.</summary>
    /// <param name="bytes">The record.</param>
    /// <param name="id">Its id.</param>
    /// <returns>The number of env cells and the buildings.</returns>
    public static (uint NumCells, List<BuildingRecord> Buildings) LandblockInfo(byte[] bytes, uint id)
    {
        var r = new RecordReader(bytes, $"LandblockInfo 0x{id:X8}");
        r.Id(id);
        uint numCells = r.U32("numCells");
        r.Skip(32 * r.Count(r.U32("numObjects"), 32, "numObjects", 8), "objects");
        int at = r.pos;
        int numBuildings = r.Count(r.U16("numBuildings"), 40, "numBuildings", at);
        ushort packMask = r.U16("packMask");
        var buildings = new List<BuildingRecord>(numBuildings);
        for (int i = 0; i < numBuildings; i++)
        {
            string f = $"buildings[{i}]";
            r.Skip(4, f + ".modelId");
            var frame = r.Frame(f + ".frame");
            r.Skip(4, f + ".numLeaves");
            int portalsAt = r.pos;
            var portals = new BldPortal[r.Count(r.U32(f + ".numPortals"), 8, f + ".numPortals", portalsAt)];
            for (int k = 0; k < portals.Length; k++)
            {
                string g = $"{f}.portals[{k}]";
                portals[k] = new BldPortal(r.U16(g + ".flags"), r.U16(g + ".otherCellId"), r.U16(g + ".otherPortalId"));
                int stabsAt = r.pos;
                r.Skip(2 * r.Count(r.U16(g + ".numStabs"), 2, g + ".numStabs", stabsAt), g + ".stabList");
                r.Align(g);
            }

            buildings.Add(new BuildingRecord(frame, portals));
        }

        if ((packMask & 1) != 0)
        {
            int tableAt = r.pos;
            int entries = r.Count(r.U16("restrictions.count"), 8, "restrictions.count", tableAt);
            r.Skip(2 + (8 * entries), "restrictions");
        }

        r.End();
        return (numCells, buildings);
    }

    /// <summary>Checks a Landblock record: its id and its length (membership needs no terrain: land cells are flat squares).</summary>
    /// <param name="bytes">The record.</param>
    /// <param name="id">Its id.</param>
    /// <returns>hasObjects as ACE reads it: true only when it is 1 (then the block's LandblockInfo is read).</returns>
    public static bool Landblock(byte[] bytes, uint id)
    {
        var r = new RecordReader(bytes, $"Landblock 0x{id:X8}");
        r.Id(id);
        bool hasObjects = r.U32("hasObjects") == 1;
        r.Skip((2 * 81) + 81, "terrain/height");
        r.Align("height");
        r.End();
        return hasObjects;
    }

    private static uint Tag(string letters) => ((uint)letters[0] << 24) | ((uint)letters[1] << 16) | ((uint)letters[2] << 8) | letters[3];

    private CellStructRecord CellStruct(string at)
    {
        int countsAt = pos;
        uint numPolygons = U32(at + ".numPolygons");
        uint numPhysics = U32(at + ".numPhysicsPolygons");
        uint numPortals = U32(at + ".numPortals");
        int typeAt = pos;
        int vertexType = I32(at + ".vertexType");
        Check(vertexType == 1, at + ".vertexType", typeAt, $"{vertexType}, must be 1");
        int verticesAt = pos;
        int numVertices = Count(U32(at + ".numVertices"), 28, at + ".numVertices", verticesAt);
        var vertices = new Dictionary<ushort, Vector3>(numVertices);
        for (int i = 0; i < numVertices; i++)
        {
            string f = $"{at}.vertices[{i}]";
            int idAt = pos;
            ushort vid = U16(f + ".id");
            int uvsAt = pos;
            int numUvs = Count(U16(f + ".numUVs"), 8, f + ".numUVs", uvsAt);
            Check(vertices.TryAdd(vid, Vec(f + ".origin")), f + ".id", idAt, $"duplicate vertex id {vid}");
            Skip(12 + (8 * numUvs), f + ".normal/uvs");
        }

        var polygons = Polygons(numPolygons, at + ".polygons", countsAt);
        var portals = new ushort[Count(numPortals, 2, at + ".numPortals", countsAt + 8)];
        for (int i = 0; i < portals.Length; i++)
        {
            portals[i] = U16($"{at}.portalPolygonIds[{i}]");
        }

        Align(at + ".portalPolygonIds");
        var cellBsp = new List<BspNode>();
        ReadTree(Tree.Cell, cellBsp, at + ".cellBsp", 0);
        Polygons(numPhysics, at + ".physicsPolygons", countsAt + 4);
        ReadTree(Tree.Physics, null, at + ".physicsBsp", 0);
        int drawingAt = pos;
        uint hasDrawing = U32(at + ".hasDrawingBSP");
        Check(hasDrawing <= 1, at + ".hasDrawingBSP", drawingAt, $"{hasDrawing}, expected 0 or 1");
        if (hasDrawing != 0)
        {
            ReadTree(Tree.Drawing, null, at + ".drawingBsp", 0);
        }

        Align(at);
        return new CellStructRecord(vertices, polygons, portals, [.. cellBsp]);
    }

    private Dictionary<ushort, ushort[]> Polygons(uint count, string at, int countAt)
    {
        int n = Count(count, 12, at + " count", countAt);
        var polygons = new Dictionary<ushort, ushort[]>(n);
        for (int i = 0; i < n; i++)
        {
            string f = $"{at}[{i}]";
            int idAt = pos;
            ushort id = U16(f + ".id");
            int numPts = U8(f + ".numPts");
            byte stippling = U8(f + ".stippling");
            int sidesAt = pos;
            int sides = I32(f + ".sidesType");
            Check(sides is >= 0 and <= 3, f + ".sidesType", sidesAt, $"{sides}, expected 0..3");
            Skip(4, f + ".surfaces");
            var ids = new ushort[numPts];
            for (int k = 0; k < numPts; k++)
            {
                ids[k] = U16(f + ".vertexIds");
            }

            // UV index bytes: positive unless NoPos (4); negative for Clockwise (2) unless NoNeg (8).
            Skip(((stippling & 4) == 0 ? numPts : 0) + (sides == 2 && (stippling & 8) == 0 ? numPts : 0), f + ".uvIndices");
            Check(polygons.TryAdd(id, ids), f + ".id", idAt, $"duplicate polygon id {id}");
        }

        return polygons;
    }

    // Depth first; a node's children come right after its plane, before its own trailing fields. Only the cell tree
    // is kept (nodes != null); the physics and drawing trees are read to step over them.
    private int ReadTree(Tree tree, List<BspNode>? nodes, string field, int depth)
    {
        int at = pos;
        Check(depth < MaxTreeDepth, field, at, $"BSP tree deeper than {MaxTreeDepth} nodes");
        uint tag = U32(field + ".tag");
        int self = nodes?.Count ?? -1;
        if (tag == Leaf)
        {
            Skip(4, field + ".leafIndex");
            if (tree == Tree.Physics)
            {
                Skip(4 + 16, field + ".solid/sphere");
                PolygonIds(field);
            }

            nodes?.Add(new BspNode(default, -1, -1, true));
            return self;
        }

        bool positive = tag == Port || Both.Contains(tag) || PositiveOnly.Contains(tag);
        bool negative = tag == Port || Both.Contains(tag) || NegativeOnly.Contains(tag);
        Check(positive || negative, field + ".tag", at, $"unknown BSP tag 0x{tag:X8}");
        var normal = Vec(field + ".plane.normal");
        var plane = new CellPlane(normal, F32(field + ".plane.d"));
        nodes?.Add(default);
        int pos1 = positive ? ReadTree(tree, nodes, field + ".pos", depth + 1) : -1;
        int neg1 = negative ? ReadTree(tree, nodes, field + ".neg", depth + 1) : -1;
        if (nodes is not null)
        {
            nodes[self] = new BspNode(plane, pos1, neg1, false);
        }

        if (tag == Port)
        {
            if (tree == Tree.Drawing)
            {
                Skip(16, field + ".sphere");
                int countsAt = pos;
                uint polys = U32(field + ".numPolys"), portals = U32(field + ".numPortals");
                Skip((2 * Count(polys, 2, field + ".numPolys", countsAt)) + (4 * Count(portals, 4, field + ".numPortals", countsAt + 4)), field + ".polys/portals");
            }

            return self;
        }

        if (tree != Tree.Cell)
        {
            Skip(16, field + ".sphere");
        }

        if (tree == Tree.Drawing)
        {
            PolygonIds(field);
        }

        return self;
    }

    private void PolygonIds(string field)
    {
        int at = pos;
        Skip(2 * Count(U32(field + ".numPolys"), 2, field + ".numPolys", at), field + ".polys");
    }

    private void Id(uint expected)
    {
        uint id = U32("id");
        Check(id == expected, "id", 0, $"0x{id:X8} is not the record's name 0x{expected:X8}");
    }

    private Frame Frame(string field)
    {
        var origin = Vec(field + ".origin");
        float w = F32(field + ".rotation.w"), x = F32(field + ".rotation.x"), y = F32(field + ".rotation.y"), z = F32(field + ".rotation.z");
        return new Frame(origin, new Quaternion(x, y, z, w));
    }

    private Vector3 Vec(string field)
    {
        float x = F32(field + ".x"), y = F32(field + ".y"), z = F32(field + ".z");
        return new Vector3(x, y, z);
    }

    private float F32(string field)
    {
        int at = pos;
        float v = BitConverter.UInt32BitsToSingle(U32(field));
        Check(float.IsFinite(v), field, at, "not a finite number");
        return v;
    }

    private byte U8(string field) => Take(1, field)[0];

    private ushort U16(string field) => BinaryPrimitives.ReadUInt16LittleEndian(Take(2, field));

    private uint U32(string field) => BinaryPrimitives.ReadUInt32LittleEndian(Take(4, field));

    private int I32(string field) => BinaryPrimitives.ReadInt32LittleEndian(Take(4, field));

    private void Skip(int n, string field) => Take(n, field);

    private void Align(string field) => Skip((4 - (pos % 4)) % 4, field + " (ALIGN padding)");

    private int Count(long count, int minBytes, string field, int at)
    {
        Check(count * minBytes <= data.Length - pos, field, at, $"count {count} needs at least {count * minBytes} bytes, {data.Length - pos} left");
        return (int)count;
    }

    private void End() => Check(pos == data.Length, "end of record", pos, $"{data.Length - pos} trailing byte(s)");

    private void Check(bool ok, string field, int at, string problem)
    {
        if (!ok)
        {
            throw new InputException($"{record}: {field} at byte {at}: {problem}");
        }
    }

    private ReadOnlySpan<byte> Take(int n, string field)
    {
        Check(n <= data.Length - pos, field, pos, $"the record ends ({data.Length - pos} byte(s) left, {n} needed)");
        var span = data.AsSpan(pos, n);
        pos += n;
        return span;
    }
}
