using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>A scene written as records: each record's bytes and the manifest.</summary>
/// <param name="Records">The records and their bytes, in manifest order.</param>
/// <param name="Manifest">The manifest.</param>
public sealed record DatExport(IReadOnlyList<(ManifestRecord Record, byte[] Bytes)> Records, DatManifest Manifest);

/// <summary>
/// Writes a scene as retail records (docs/dat-scenes.md): a flat Landblock per loaded block, a LandblockInfo per block
/// with buildings or loaded cells, one EnvCell per cell, one Environment holding a CellStruct per distinct geometry.
/// </summary>
public static class DatSceneWriter
{
    /// <summary>The model id written for every building (scenes have no models).</summary>
    public const uint BuildingModel = 0x01000001;

    /// <summary>The one surface every EnvCell lists (ACE reads it as 0x08000001).</summary>
    public const ushort DummySurface = 0x0001;

    /// <summary>Writes the records and manifest.</summary>
    /// <param name="scene">A valid scene.</param>
    /// <param name="title">Title for the manifest.</param>
    /// <param name="source">Source for the manifest.</param>
    /// <returns>The export.</returns>
    /// <exception cref="InputFormatException">The scene exceeds what the records hold (more than 255 portals in a cell, ...).</exception>
    public static DatExport Write(Scene scene, string title, string source)
    {
        var records = new List<(ManifestRecord, byte[])>();

        // LandblockInfo: blocks in order of their first building, then blocks that hold loaded cells only. Their
        // Landblock records say hasObjects 1, or a reader that honours the flag (ACE) never reads them.
        var infoBlocks = scene.Buildings.Select(b => b.Block).Concat(scene.Cells.Select(c => c.Id.Landblock)).Distinct().ToList();
        foreach (var b in scene.Blocks)
        {
            uint id = ((uint)b.Value << 16) | 0xFFFF;
            records.Add((new ManifestRecord(id, false, RecordType.Landblock), LandblockRecord.WriteFlat(id, infoBlocks.Contains(b))));
        }

        foreach (var block in infoBlocks)
        {
            uint id = ((uint)block.Value << 16) | 0xFFFE;
            var lows = scene.Cells.Where(c => c.Id.Landblock == block).Select(c => (int)c.Id.Low).ToList();
            uint numCells = lows.Count == 0 ? 0u : (uint)(lows.Max() - LandDefs.FirstEnvCellId + 1);
            var buildings = scene.Buildings.Where(b => b.Block == block).Select(b => new DatBuilding(
                BuildingModel,
                b.Origin,
                Quaternion.Identity,
                0,
                [.. b.Portals.Select(p => new DatBldPortal(0, p.Cell, p.Portal, []))])).ToList();
            Require(buildings.Count <= ushort.MaxValue, $"block {block} has {buildings.Count} buildings; a LandblockInfo holds at most 65535");
            records.Add((new ManifestRecord(id, false, RecordType.LandblockInfo), new LandblockInfoRecord(id, numCells, buildings).Write()));
        }

        var keys = new Dictionary<CellGeometryKey, ushort>();
        var structs = new List<CellStructRecord>();
        var elsewhere = new List<(CellId, IReadOnlyList<CellId>)>();
        var cellRecords = new List<(ManifestRecord, byte[])>();
        foreach (var cell in scene.Cells)
        {
            Require(cell.Portals.Count <= byte.MaxValue, $"cell {cell.Id} has {cell.Portals.Count} portals; an EnvCell holds at most 255");
            long t = AcPhys.Formats.Values.WireProfile.Start(); // no closure per cell (issue 26)
            var key = CellGeometryKey.Of(cell);
            AcPhys.Formats.Values.WireProfile.Stop("dat write: GeometryKey", t);
            if (!keys.TryGetValue(key, out ushort index))
            {
                Require(structs.Count <= ushort.MaxValue, "more than 65536 distinct cell geometries");
                index = (ushort)structs.Count;
                keys.Add(key, index);
                t = AcPhys.Formats.Values.WireProfile.Start();
                structs.Add(CellStructBuilder.Build(index, cell));
                AcPhys.Formats.Values.WireProfile.Stop("dat write: CellStructBuilder.Build", t);
            }

            var cs = structs[index];
            var portals = cell.Portals.Select((p, i) => new DatCellPortal(CellPortal.FlagsFor(p.PortalSide, p.IsExit), cs.PortalPolygonIds[i], p.Other, p.OtherPortal)).ToList();
            var local = cell.Visible.Where(v => v.Landblock == cell.Id.Landblock).Select(v => v.Low).ToList();
            var foreign = cell.Visible.Where(v => v.Landblock != cell.Id.Landblock).ToList();
            if (foreign.Count > 0)
            {
                elsewhere.Add((cell.Id, foreign));
            }

            var record = new EnvCellRecord(cell.Id.Value, 0, [DummySurface], unchecked((ushort)RecordIds.EnvironmentId), index, cell.Origin, cell.Rotation, portals, local);
            cellRecords.Add((new ManifestRecord(cell.Id.Value, false, RecordType.EnvCell), record.Write()));
        }

        records.AddRange(cellRecords);
        records.Insert(0, (new ManifestRecord(RecordIds.EnvironmentId, true, RecordType.Environment), AcPhys.Formats.Values.WireProfile.Time("dat write: Environment", () => EnvironmentCodec.Write(RecordIds.EnvironmentId, structs))));
        var manifest = new DatManifest(title, source, [.. records.Select(r => r.Item1)], scene.Blocks, scene.UnloadedBlocks, scene.UnloadedCells, elsewhere);
        return new DatExport(records, manifest);
    }

    private static void Require(bool ok, string message)
    {
        if (!ok)
        {
            throw new InputFormatException("scene cannot be written as records: " + message);
        }
    }

    // The message is written only when the check fails (issue 26: per cell and block it was written every time).
    private static void Require(bool ok, [System.Runtime.CompilerServices.InterpolatedStringHandlerArgument("ok")] ref FailureText message)
    {
        if (!ok)
        {
            throw new InputFormatException("scene cannot be written as records: " + message.Text());
        }
    }
}
