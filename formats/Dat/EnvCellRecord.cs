using System.Numerics;

namespace AcPhys.Formats.Dat;

/// <summary>An EnvCell portal as stored (facts §5.4): flags (1 ExactMatch, 2 clear ⇒ PortalSide, 4 outside), polygon, other cell and portal.</summary>
/// <param name="Flags">The flags.</param>
/// <param name="PolygonId">A polygon of the cell's CellStruct.</param>
/// <param name="OtherCellId">Low word of the cell behind; 0xFFFF outside.</param>
/// <param name="OtherPortalId">Index into that cell's portals; 0xFFFF none.</param>
public readonly record struct DatCellPortal(ushort Flags, ushort PolygonId, ushort OtherCellId, ushort OtherPortalId);

/// <summary>An EnvCell record 0xAABBcccc (dat-records.md, EnvCell — no ALIGN anywhere).</summary>
/// <param name="Id">The full cell id.</param>
/// <param name="Flags">1 SeenOutside, 2 HasStaticObjs, 8 HasRestrictionObj.</param>
/// <param name="Surfaces">Surface ids (low words; ACE ORs 0x08000000).</param>
/// <param name="EnvironmentId">Low word of the Environment (ACE ORs 0x0D000000).</param>
/// <param name="CellStructure">The CellStruct key.</param>
/// <param name="Origin">Frame origin in the block frame.</param>
/// <param name="Rotation">Frame rotation.</param>
/// <param name="Portals">Portals in dat order.</param>
/// <param name="VisibleCells">Low words of the visible cells (same block).</param>
public sealed record EnvCellRecord(uint Id, uint Flags, IReadOnlyList<ushort> Surfaces, ushort EnvironmentId, ushort CellStructure, Vector3 Origin, Quaternion Rotation, IReadOnlyList<DatCellPortal> Portals, IReadOnlyList<ushort> VisibleCells)
{
    /// <summary>Gets the static objects (flag 2), as (id, origin, rotation).</summary>
    public IReadOnlyList<(uint Id, Vector3 Origin, Quaternion Rotation)> Stabs { get; init; } = [];

    /// <summary>Gets the restriction object (flag 8), or 0.</summary>
    public uint RestrictionObject { get; init; }

    /// <summary>Writes the record.</summary>
    /// <returns>The bytes.</returns>
    public byte[] Write()
    {
        var w = new ByteWriter();
        w.U32(Id);
        w.U32(Flags);
        w.U32(Id); // ACE skips these 4 bytes; retail stores the cell id again
        w.U8((byte)Surfaces.Count);
        w.U8((byte)Portals.Count);
        w.U16((ushort)VisibleCells.Count);
        foreach (ushort s in Surfaces)
        {
            w.U16(s);
        }

        w.U16(EnvironmentId);
        w.U16(CellStructure);
        w.Frame(Origin, Rotation); // unaligned when the surface count is odd: ACE reads it right there
        foreach (var p in Portals)
        {
            w.U16(p.Flags);
            w.U16(p.PolygonId);
            w.U16(p.OtherCellId);
            w.U16(p.OtherPortalId);
        }

        foreach (ushort v in VisibleCells)
        {
            w.U16(v);
        }

        if ((Flags & 2) != 0)
        {
            w.U32((uint)Stabs.Count);
            foreach (var (id, origin, rotation) in Stabs)
            {
                w.U32(id);
                w.Frame(origin, rotation);
            }
        }

        if ((Flags & 8) != 0)
        {
            w.U32(RestrictionObject);
        }

        return w.ToArray();
    }

    /// <summary>Reads the record strictly.</summary>
    /// <param name="data">The bytes.</param>
    /// <param name="expectedId">The id the record must carry.</param>
    /// <returns>The record.</returns>
    /// <exception cref="InputFormatException">Any defect.</exception>
    public static EnvCellRecord Read(byte[] data, uint expectedId) => ByteReader.Strictly(named => Read(data, expectedId, named));

    internal static EnvCellRecord Read(byte[] data, uint expectedId, bool named)
    {
        var r = new ByteReader(data, "EnvCell", expectedId, named);
        uint id = r.U32("id");
        r.Require(id == expectedId, "id", 0, $"record id {RecordIds.Text(id)} is not its name {RecordIds.Text(expectedId)}");
        uint flags = r.U32("flags");
        r.Require((flags & ~0xBu) == 0, "flags", 4, $"unknown flag bits 0x{flags & ~0xBu:X} (known: 1, 2, 8)");
        uint again = r.U32("cell id (again)");
        r.Require(again == id, "cell id (again)", 8, $"{RecordIds.Text(again)}, expected the cell id {RecordIds.Text(id)}");
        int numSurfaces = r.U8("numSurfaces");
        int numPortals = r.U8("numPortals");
        int numStabs = r.U16("numStabs");
        r.Count(numSurfaces + 2 + 14 + (4 * numPortals) + numStabs, 2, "numSurfaces/numPortals/numStabs", 12);
        var surfaces = new ushort[numSurfaces];
        for (int i = 0; i < numSurfaces; i++)
        {
            surfaces[i] = r.U16(r.Path($"surfaces[{i}]"));
        }

        ushort environment = r.U16("environmentId");
        ushort cellStructure = r.U16("cellStructure");
        var (origin, rotation) = r.Frame("position");
        var portals = new DatCellPortal[numPortals];
        for (int i = 0; i < numPortals; i++)
        {
            string? f = r.Path($"portals[{i}]");
            portals[i] = new DatCellPortal(r.U16(f + ".flags"), r.U16(f + ".polygonId"), r.U16(f + ".otherCellId"), r.U16(f + ".otherPortalId"));
        }

        var visible = new ushort[numStabs];
        for (int i = 0; i < numStabs; i++)
        {
            visible[i] = r.U16(r.Path($"visibleCells[{i}]"));
        }

        var stabs = new List<(uint, Vector3, Quaternion)>();
        if ((flags & 2) != 0)
        {
            int at = r.Position;
            int n = r.Count(r.U32("staticObjects.count"), 32, "staticObjects.count", at);
            for (int i = 0; i < n; i++)
            {
                uint sid = r.U32(r.Path($"staticObjects[{i}].id"));
                var (o, q) = r.Frame(r.Path($"staticObjects[{i}].frame"));
                stabs.Add((sid, o, q));
            }
        }

        uint restriction = (flags & 8) != 0 ? r.U32("restrictionObject") : 0;
        r.End();
        return new EnvCellRecord(id, flags, surfaces, environment, cellStructure, origin, rotation, portals, visible) { Stabs = stabs, RestrictionObject = restriction };
    }
}
