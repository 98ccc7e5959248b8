using System.Numerics;

namespace AcPhys.Formats.Dat;

/// <summary>
/// The Environment record 0x0D?????? (dat-records.md, Environment and CellStruct): id, a plain u32 count, then
/// (key, CellStruct) pairs. The CellStruct's ALIGN points are the two marked in the layout: after the portal
/// polygon ids and at its end; nowhere else (hasDrawingBSP can sit at an odd offset).
/// </summary>
public static class EnvironmentCodec
{
    /// <summary>Writes an Environment record.</summary>
    /// <param name="id">The record id.</param>
    /// <param name="structs">The CellStructs.</param>
    /// <returns>The bytes.</returns>
    public static byte[] Write(uint id, IReadOnlyList<CellStructRecord> structs)
    {
        var w = new ByteWriter(2048 * structs.Count);
        w.U32(id);
        w.U32((uint)structs.Count);
        for (int k = 0; k < structs.Count; k++)
        {
            w.U32(structs[k].Key);
            WriteBody(w, structs[k]);
        }

        return w.ToArray();
    }

    // Everything after the key. The writer is 4-aligned here (record header, keys and bodies are multiples of 4), so
    // the body's alignment padding does not depend on where it lands. Index loops throughout: a foreach over an
    // IReadOnlyList allocates an enumerator per list, per vertex and polygon.
    private static void WriteBody(ByteWriter w, CellStructRecord s)
    {
        w.U32((uint)s.Polygons.Count);
        w.U32((uint)s.PhysicsPolygons.Count);
        w.U32((uint)s.PortalPolygonIds.Count);
        w.I32(1); // vertex type: must be 1
        w.U32((uint)s.Vertices.Count);
        for (int i = 0; i < s.Vertices.Count; i++)
        {
            var v = s.Vertices[i];
            w.U16(v.Id);
            w.U16((ushort)v.Uvs.Count);
            w.Vec(v.Origin);
            w.Vec(v.Normal);
            for (int u = 0; u < v.Uvs.Count; u++)
            {
                w.F32(v.Uvs[u].X);
                w.F32(v.Uvs[u].Y);
            }
        }

        for (int i = 0; i < s.Polygons.Count; i++)
        {
            Polygon(w, s.Polygons[i]);
        }

        for (int i = 0; i < s.PortalPolygonIds.Count; i++)
        {
            w.U16(s.PortalPolygonIds[i]);
        }

        w.Align();
        BspCodec.Write(w, s.CellBsp, BspTreeType.Cell);
        for (int i = 0; i < s.PhysicsPolygons.Count; i++)
        {
            Polygon(w, s.PhysicsPolygons[i]);
        }

        BspCodec.Write(w, s.PhysicsBsp, BspTreeType.Physics);
        w.U32(s.DrawingBsp is null ? 0u : 1u);
        if (s.DrawingBsp is { } drawing)
        {
            BspCodec.Write(w, drawing, BspTreeType.Drawing);
        }

        w.Align();
    }

    /// <summary>Reads an Environment record strictly (duplicate keys, bad vertex types, unknown tags and trailing bytes refused).</summary>
    /// <param name="data">The bytes.</param>
    /// <param name="expectedId">The id the record must carry.</param>
    /// <returns>The CellStructs by key, in record order.</returns>
    /// <exception cref="InputFormatException">Any defect.</exception>
    public static IReadOnlyList<CellStructRecord> Read(byte[] data, uint expectedId) => ByteReader.Strictly(named => Read(data, expectedId, named));

    internal static List<CellStructRecord> Read(byte[] data, uint expectedId, bool named)
    {
        var r = new ByteReader(data, "Environment", expectedId, named);
        uint id = r.U32("id");
        r.Require(id == expectedId, "id", 0, $"record id {RecordIds.Text(id)} is not its name {RecordIds.Text(expectedId)}");
        int count = r.Count(r.U32("numCellStructs"), 4 + 24, "numCellStructs", 4);
        var keys = new HashSet<uint>();
        var result = new List<CellStructRecord>(count);
        for (int i = 0; i < count; i++)
        {
            int at = r.Position;
            uint key = r.U32(r.Path($"cellStructs[{i}].key"));
            r.Require(keys.Add(key), r.Path($"cellStructs[{i}].key"), at, $"duplicate CellStruct key {key}");
            result.Add(CellStruct(r, key, r.Path($"cellStructs[{i}]")));
        }

        r.End();
        return result;
    }

    private static CellStructRecord CellStruct(ByteReader r, uint key, string? at)
    {
        int countsAt = r.Position;
        uint numPolygons = r.U32(at + ".numPolygons");
        uint numPhysics = r.U32(at + ".numPhysicsPolygons");
        uint numPortals = r.U32(at + ".numPortals");
        int typeAt = r.Position;
        int vertexType = r.I32(at + ".vertexType");
        r.Require(vertexType == 1, at + ".vertexType", typeAt, $"vertex type {vertexType}, must be 1");
        int vAt = r.Position;
        int numVertices = r.Count(r.U32(at + ".numVertices"), 28, at + ".numVertices", vAt);
        var vertices = new List<DatVertex>(numVertices);
        var vertexIds = new HashSet<ushort>();
        for (int i = 0; i < numVertices; i++)
        {
            string? f = r.Path($"{at}.vertices[{i}]");
            int idAt = r.Position;
            ushort id = r.U16(f + ".id");
            r.Require(vertexIds.Add(id), f + ".id", idAt, $"duplicate vertex id {id}");
            int uvAt = r.Position;
            int numUvs = r.Count(r.U16(f + ".numUVs"), 8, f + ".numUVs", uvAt);
            var origin = r.Vec(f + ".origin");
            var normal = r.Vec(f + ".normal");
            var uvs = new Vector2[numUvs];
            for (int k = 0; k < numUvs; k++)
            {
                uvs[k] = new Vector2(r.F32(f + ".uv"), r.F32(f + ".uv"));
            }

            vertices.Add(new DatVertex(id, origin, normal, uvs));
        }

        var polygons = Polygons(r, numPolygons, r.Path($"{at}.numPolygons"), countsAt, r.Path($"{at}.polygons"));
        int portals = r.Count(numPortals, 2, at + ".numPortals", countsAt + 8);
        var portalIds = new ushort[portals];
        for (int i = 0; i < portals; i++)
        {
            portalIds[i] = r.U16(r.Path($"{at}.portalPolygonIds[{i}]"));
        }

        r.Align(r.Path($"{at}.portalPolygonIds"));
        var cellBsp = BspCodec.Read(r, BspTreeType.Cell, r.Path($"{at}.cellBsp"));
        var physics = Polygons(r, numPhysics, r.Path($"{at}.numPhysicsPolygons"), countsAt + 4, r.Path($"{at}.physicsPolygons"));
        var physicsBsp = BspCodec.Read(r, BspTreeType.Physics, r.Path($"{at}.physicsBsp"));
        int hasAt = r.Position;
        uint hasDrawing = r.U32(at + ".hasDrawingBSP");
        r.Require(hasDrawing <= 1, at + ".hasDrawingBSP", hasAt, $"expected 0 or 1, got {hasDrawing}");
        var drawing = hasDrawing != 0 ? BspCodec.Read(r, BspTreeType.Drawing, r.Path($"{at}.drawingBsp")) : null;
        r.Align(r.Path($"{at} end"));
        return new CellStructRecord(key, vertices, polygons, portalIds, cellBsp, physics, physicsBsp, drawing);
    }

    private static List<DatPolygon> Polygons(ByteReader r, uint count, string? countField, int countAt, string? at)
    {
        int n = r.Count(count, 12, countField, countAt);
        var list = new List<DatPolygon>(n);
        var ids = new HashSet<ushort>();
        for (int i = 0; i < n; i++)
        {
            string? f = r.Path($"{at}[{i}]");
            int idAt = r.Position;
            ushort id = r.U16(f + ".id");
            r.Require(ids.Add(id), f + ".id", idAt, $"duplicate polygon id {id}");
            byte numPts = r.U8(f + ".numPts");
            byte stippling = r.U8(f + ".stippling");
            int sAt = r.Position;
            int sides = r.I32(f + ".sidesType");
            r.Require(sides is >= 0 and <= 3, f + ".sidesType", sAt, $"sides type {sides}, expected 0..3");
            short pos = r.I16(f + ".posSurface");
            short neg = r.I16(f + ".negSurface");
            var vertexIds = new short[numPts];
            for (int k = 0; k < numPts; k++)
            {
                vertexIds[k] = r.I16(f + ".vertexIds");
            }

            var p = new DatPolygon(id, stippling, sides, pos, neg, vertexIds, [], []);
            var posUvs = p.HasPosUvs ? Bytes(r, numPts, f + ".posUVs") : [];
            var negUvs = p.HasNegUvs ? Bytes(r, numPts, f + ".negUVs") : [];
            list.Add(p with { PosUvs = posUvs, NegUvs = negUvs });
        }

        return list;
    }

    private static byte[] Bytes(ByteReader r, int n, string? field)
    {
        var b = new byte[n];
        for (int i = 0; i < n; i++)
        {
            b[i] = r.U8(field);
        }

        return b;
    }

    private static void Polygon(ByteWriter w, DatPolygon p)
    {
        w.U16(p.Id);
        w.U8((byte)p.VertexIds.Count);
        w.U8(p.Stippling);
        w.I32(p.SidesType);
        w.I16(p.PosSurface);
        w.I16(p.NegSurface);
        for (int i = 0; i < p.VertexIds.Count; i++)
        {
            w.I16(p.VertexIds[i]);
        }

        if (p.HasPosUvs)
        {
            for (int i = 0; i < p.PosUvs.Count; i++)
            {
                w.U8(p.PosUvs[i]);
            }
        }

        if (p.HasNegUvs)
        {
            for (int i = 0; i < p.NegUvs.Count; i++)
            {
                w.U8(p.NegUvs[i]);
            }
        }
    }
}
