using System.Numerics;

namespace AcPhys.Formats.Dat;

/// <summary>A CBldPortal (facts §5.4): flags, the env cell behind (low word, same block), its portal index (0xFFFF none), stabs.</summary>
/// <param name="Flags">Flags (2 clear ⇒ PortalSide).</param>
/// <param name="OtherCellId">Env cell low word.</param>
/// <param name="OtherPortalId">Index into that cell's portals; 0xFFFF none.</param>
/// <param name="StabList">Visible cells (low words).</param>
public sealed record DatBldPortal(ushort Flags, ushort OtherCellId, ushort OtherPortalId, IReadOnlyList<ushort> StabList);

/// <summary>A building of a LandblockInfo: model id, frame (block frame), leaves and portals.</summary>
/// <param name="ModelId">The model id.</param>
/// <param name="Origin">Frame origin in the block frame.</param>
/// <param name="Rotation">Frame rotation.</param>
/// <param name="NumLeaves">The leaf count.</param>
/// <param name="Portals">The building portals.</param>
public sealed record DatBuilding(uint ModelId, Vector3 Origin, Quaternion Rotation, uint NumLeaves, IReadOnlyList<DatBldPortal> Portals);

/// <summary>
/// A LandblockInfo record 0xAABBFFFE (dat-records.md, LandblockInfo): cell count, static objects, buildings (each
/// CBldPortal followed by ALIGN), and the optional restriction table (packMask &amp; 1).
/// </summary>
/// <param name="Id">The record id.</param>
/// <param name="NumCells">The number of env cells (0x0100 .. 0x0100 + n − 1).</param>
/// <param name="Buildings">The buildings.</param>
public sealed record LandblockInfoRecord(uint Id, uint NumCells, IReadOnlyList<DatBuilding> Buildings)
{
    /// <summary>Gets the static objects, as (id, origin, rotation).</summary>
    public IReadOnlyList<(uint Id, Vector3 Origin, Quaternion Rotation)> Objects { get; init; } = [];

    /// <summary>Gets the restriction table (packMask bit 1), or null.</summary>
    public IReadOnlyList<(uint Key, uint Value)>? Restrictions { get; init; }

    /// <summary>Writes the record.</summary>
    /// <returns>The bytes.</returns>
    public byte[] Write()
    {
        var w = new ByteWriter();
        w.U32(Id);
        w.U32(NumCells);
        w.U32((uint)Objects.Count);
        foreach (var (id, origin, rotation) in Objects)
        {
            w.U32(id);
            w.Frame(origin, rotation);
        }

        w.U16((ushort)Buildings.Count);
        w.U16(Restrictions is null ? (ushort)0 : (ushort)1);
        foreach (var b in Buildings)
        {
            w.U32(b.ModelId);
            w.Frame(b.Origin, b.Rotation);
            w.U32(b.NumLeaves);
            w.U32((uint)b.Portals.Count);
            foreach (var p in b.Portals)
            {
                w.U16(p.Flags);
                w.U16(p.OtherCellId);
                w.U16(p.OtherPortalId);
                w.U16((ushort)p.StabList.Count);
                foreach (ushort s in p.StabList)
                {
                    w.U16(s);
                }

                w.Align(); // after every CBldPortal
            }
        }

        if (Restrictions is { } table)
        {
            w.U16((ushort)table.Count);
            w.U16(0);
            foreach (var (k, v) in table)
            {
                w.U32(k);
                w.U32(v);
            }
        }

        return w.ToArray();
    }

    /// <summary>Reads the record strictly.</summary>
    /// <param name="data">The bytes.</param>
    /// <param name="expectedId">The id the record must carry.</param>
    /// <returns>The record.</returns>
    /// <exception cref="InputFormatException">Any defect.</exception>
    public static LandblockInfoRecord Read(byte[] data, uint expectedId) => ByteReader.Strictly(named => Read(data, expectedId, named));

    internal static LandblockInfoRecord Read(byte[] data, uint expectedId, bool named)
    {
        var r = new ByteReader(data, "LandblockInfo", expectedId, named);
        uint id = r.U32("id");
        r.Require(id == expectedId, "id", 0, $"record id {RecordIds.Text(id)} is not its name {RecordIds.Text(expectedId)}");
        uint numCells = r.U32("numCells");
        r.Require(numCells <= 0xFFFE - 0x0100, "numCells", 4, $"{numCells} cells do not fit the env cell ids 0x0100..0xFFFD");
        int n = r.Count(r.U32("numObjects"), 32, "numObjects", 8);
        var objects = new List<(uint, Vector3, Quaternion)>(n);
        for (int i = 0; i < n; i++)
        {
            uint oid = r.U32(r.Path($"objects[{i}].id"));
            var (o, q) = r.Frame(r.Path($"objects[{i}].frame"));
            objects.Add((oid, o, q));
        }

        int bAt = r.Position;
        int numBuildings = r.Count(r.U16("numBuildings"), 40, "numBuildings", bAt);
        ushort packMask = r.U16("packMask");
        r.Require((packMask & ~1) == 0, "packMask", bAt + 2, $"unknown bits 0x{packMask & ~1:X} (known: 1)");
        var buildings = new List<DatBuilding>(numBuildings);
        for (int i = 0; i < numBuildings; i++)
        {
            string? f = r.Path($"buildings[{i}]");
            uint model = r.U32(f + ".modelId");
            var (origin, rotation) = r.Frame(f + ".frame");
            uint leaves = r.U32(f + ".numLeaves");
            int pAt = r.Position;
            int numPortals = r.Count(r.U32(f + ".numPortals"), 8, f + ".numPortals", pAt);
            var portals = new List<DatBldPortal>(numPortals);
            for (int k = 0; k < numPortals; k++)
            {
                string? g = r.Path($"{f}.portals[{k}]");
                ushort flags = r.U16(g + ".flags");
                ushort other = r.U16(g + ".otherCellId");
                ushort otherPortal = r.U16(g + ".otherPortalId");
                int sAt = r.Position;
                int numStabs = r.Count(r.U16(g + ".numStabs"), 2, g + ".numStabs", sAt);
                var stabs = new ushort[numStabs];
                for (int s = 0; s < numStabs; s++)
                {
                    stabs[s] = r.U16(g + ".stabList");
                }

                r.Align(g);
                portals.Add(new DatBldPortal(flags, other, otherPortal, stabs));
            }

            buildings.Add(new DatBuilding(model, origin, rotation, leaves, portals));
        }

        List<(uint, uint)>? restrictions = null;
        if ((packMask & 1) != 0)
        {
            int tAt = r.Position;
            int count = r.Count(r.U16("restrictions.count"), 8, "restrictions.count", tAt);
            _ = r.U16("restrictions.bucketSize");
            restrictions = new List<(uint, uint)>(count);
            for (int i = 0; i < count; i++)
            {
                restrictions.Add((r.U32(r.Path($"restrictions[{i}].key")), r.U32(r.Path($"restrictions[{i}].value"))));
            }
        }

        r.End();
        return new LandblockInfoRecord(id, numCells, buildings) { Objects = objects, Restrictions = restrictions };
    }
}
