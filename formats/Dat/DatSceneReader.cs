using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Scenes;

namespace AcPhys.Formats.Dat;

/// <summary>
/// Reads records back into a scene through their manifest (docs/dat-scenes.md, "Reading"): every record parsed
/// strictly, cross-references checked (environment, CellStruct keys, polygons, flags against other cell ids), and the
/// result validated as a scene file would be.
/// </summary>
public static class DatSceneReader
{
    /// <summary>Reads the scene.</summary>
    /// <param name="manifest">The manifest.</param>
    /// <param name="load">The bytes of a record.</param>
    /// <returns>The scene.</returns>
    /// <exception cref="InputFormatException">Any defect.</exception>
    public static Scene Read(DatManifest manifest, Func<ManifestRecord, byte[]> load)
    {
        var seen = new HashSet<(uint, bool)>();
        foreach (var r in manifest.Records)
        {
            Require(seen.Add((r.Id, r.PortalDat)), $"manifest.json: record {RecordIds.Text(r.Id)} is listed twice");
            Require(RecordIds.TypeOf(r.Id, r.PortalDat) == r.Type, $"manifest.json: record {RecordIds.Text(r.Id)} in the {(r.PortalDat ? "portal" : "cell")} dat cannot be a {r.Type}");
        }

        Require(manifest.Records.Select(r => r.File).Distinct().Count() == manifest.Records.Count, "manifest.json: two records share a file name (a cell-dat and a portal-dat record with one id cannot share a folder)");

        var environments = new Dictionary<ushort, Dictionary<uint, CellStructRecord>>();
        foreach (var r in manifest.Records.Where(r => r.Type == RecordType.Environment))
        {
            Require((r.Id & 0xFFFF0000) == 0x0D000000, $"Environment {RecordIds.Text(r.Id)}: an EnvCell names environments by a low word, so the id must be 0x0D00xxxx");
            environments[(ushort)r.Id] = AcPhys.Formats.Values.WireProfile.Time("dat read: Environment", () => EnvironmentCodec.Read(load(r), r.Id)).ToDictionary(s => s.Key);
        }

        var landblocks = new HashSet<LandblockId>();
        var withoutObjects = new HashSet<LandblockId>();
        foreach (var r in manifest.Records.Where(r => r.Type == RecordType.Landblock))
        {
            var block = new LandblockId((ushort)(r.Id >> 16));
            landblocks.Add(block);
            if (!LandblockRecord.ReadFlat(load(r), r.Id))
            {
                withoutObjects.Add(block);
            }
        }

        Require(landblocks.SetEquals(manifest.Blocks), $"manifest.json: the Landblock records ({string.Join(", ", landblocks)}) are not the loaded blocks ({string.Join(", ", manifest.Blocks)})");

        var cells = new List<SceneCell>();
        var elsewhere = manifest.VisibleElsewhere.ToDictionary(e => e.Cell, e => e.Visible);
        foreach (var r in manifest.Records.Where(r => r.Type == RecordType.EnvCell))
        {
            long t = AcPhys.Formats.Values.WireProfile.Start(); // no closure per cell (issue 26)
            cells.Add(Cell(EnvCellRecord.Read(load(r), r.Id), environments, elsewhere.GetValueOrDefault(new CellId(r.Id)) ?? []));
            AcPhys.Formats.Values.WireProfile.Stop("dat read: EnvCell + cell", t);
        }

        foreach (var (cell, _) in manifest.VisibleElsewhere)
        {
            Require(cells.Any(c => c.Id == cell), $"manifest.json: visibleElsewhere names {cell}, which has no EnvCell record");
        }

        var buildings = new List<SceneBuilding>();
        // A loaded block whose Landblock says hasObjects 0 has its LandblockInfo skipped, as ACE skips it (dat-records.md):
        // read the records as a faithful port does, so the scene compared with is the scene the port sees.
        foreach (var r in manifest.Records.Where(r => r.Type == RecordType.LandblockInfo && !withoutObjects.Contains(new LandblockId((ushort)(r.Id >> 16)))))
        {
            var info = LandblockInfoRecord.Read(load(r), r.Id);
            var block = new LandblockId((ushort)(r.Id >> 16));
            string where = "LandblockInfo " + RecordIds.Text(r.Id);
            foreach (var c in cells.Where(c => c.Id.Landblock == block))
            {
                Require(c.Id.Low < LandDefs.FirstEnvCellId + info.NumCells, $"{where}: numCells at byte 4: {info.NumCells} cells end before {c.Id}");
            }

            for (int i = 0; i < info.Buildings.Count; i++)
            {
                var b = info.Buildings[i];
                Require(b.Rotation == Quaternion.Identity, $"{where}: buildings[{i}].frame: rotation (W, X, Y, Z) = ({b.Rotation.W}, {b.Rotation.X}, {b.Rotation.Y}, {b.Rotation.Z}); scenes carry only identity");
                for (int k = 0; k < b.Portals.Count; k++)
                {
                    Require((b.Portals[k].Flags & ~3) == 0, $"{where}: buildings[{i}].portals[{k}].flags: unknown bits 0x{b.Portals[k].Flags & ~3:X}");
                }

                buildings.Add(new SceneBuilding(block, b.Origin, [.. b.Portals.Select(p => new SceneBldPortal(p.OtherCellId, p.OtherPortalId))]));
            }
        }

        var scene = new Scene(manifest.Blocks, buildings, cells) { UnloadedBlocks = manifest.UnloadedBlocks, UnloadedCells = manifest.UnloadedCells };
        try
        {
            // The same checks a scene file gets (references, declared blocks, unit quaternions, one building per land
            // cell), on the scene as built: no JSON round trip (issue #26), the same first message.
            return AcPhys.Formats.Values.WireProfile.Time("dat read: SceneRules.Check", () => new SceneRules("records").Check(scene, "$"));
        }
        catch (InputFormatException e)
        {
            throw new InputFormatException("the scene the records describe is not valid: " + e.Message, e);
        }
    }

    private static SceneCell Cell(EnvCellRecord r, Dictionary<ushort, Dictionary<uint, CellStructRecord>> environments, IReadOnlyList<CellId> elsewhere)
    {
        string where = "EnvCell " + RecordIds.Text(r.Id);
        var id = new CellId(r.Id);
        Require(id.IsEnv, $"{where}: id at byte 0: not an env cell id");
        var structs = environments.GetValueOrDefault(r.EnvironmentId)
            ?? throw new InputFormatException($"{where}: environmentId: Environment 0x0D00{r.EnvironmentId:X4} is not in the folder");
        var cs = structs.GetValueOrDefault(r.CellStructure)
            ?? throw new InputFormatException($"{where}: cellStructure: Environment 0x0D00{r.EnvironmentId:X4} has no CellStruct {r.CellStructure}");
        long t = AcPhys.Formats.Values.WireProfile.Start();
        var pieces = CellStructPieces.Of(cs.CellBsp, $"Environment 0x0D00{r.EnvironmentId:X4} cellStructs[key {cs.Key}].cellBsp");
        AcPhys.Formats.Values.WireProfile.Stop("dat read: cell pieces from BSP", t);
        var portals = new List<ScenePortal>();
        for (int i = 0; i < r.Portals.Count; i++)
        {
            var p = r.Portals[i];
            string f = $"{where}: portals[{i}]";
            Require((p.Flags & ~7) == 0, $"{f}.flags: unknown bits 0x{p.Flags & ~7:X} (known: 1 ExactMatch, 2, 4 outside)");
            bool exit = p.OtherCellId == CellPortal.Outside;
            Require(((p.Flags & CellPortal.OutsideFlag) != 0) == exit, $"{f}.flags: flag 4 (outside) {((p.Flags & 4) != 0 ? "set" : "clear")} but otherCellId 0x{p.OtherCellId:X4} (retail reads the flag, ACE the id: they must agree)");
            t = AcPhys.Formats.Values.WireProfile.Start();
            var plane = CellStructPieces.PortalPlane(cs, p.PolygonId, f + ".polygonId");
            AcPhys.Formats.Values.WireProfile.Stop("dat read: portal plane", t);
            portals.Add(new ScenePortal(plane, p.OtherCellId, (p.Flags & CellPortal.NegativeSideFlag) == 0, p.OtherPortalId));
        }

        var visible = r.VisibleCells.Select(v => id.WithLow(v)).Concat(elsewhere).ToList();
        return new SceneCell(id, r.Origin, r.Rotation, pieces, portals, visible);
    }

    private static void Require(bool ok, [System.Runtime.CompilerServices.InterpolatedStringHandlerArgument("ok")] ref FailureText message)
    {
        if (!ok)
        {
            throw new InputFormatException(message.Text());
        }
    }

    private static void Require(bool ok, string message)
    {
        if (!ok)
        {
            throw new InputFormatException(message);
        }
    }
}
