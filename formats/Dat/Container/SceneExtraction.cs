using System.Globalization;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Scenes;

namespace AcPhys.Formats.Dat.Container;

/// <summary>Why an env cell is in an extracted scene.</summary>
public enum KeepReason
{
    /// <summary>Behind a door (a building portal) of a loaded block.</summary>
    Door,

    /// <summary>Its origin lies within the place's radius.</summary>
    Near,

    /// <summary>An env cell of the chosen block (the place is the whole block).</summary>
    Block,

    /// <summary>Reached through a portal of a kept cell.</summary>
    Portal,
}

/// <summary>Why a named env cell is only a load hint (an unloaded cell) in an extracted scene.</summary>
public enum HintReason
{
    /// <summary>Named (door, portal, visible list) but the cell database has no record of it within its block's numCells.</summary>
    Missing,

    /// <summary>Reachable, but the scene already holds the most cells allowed.</summary>
    Cut,

    /// <summary>Named by a door or a visible list, but not reachable through portals from the place.</summary>
    Unreached,
}

/// <summary>What an extraction kept and why.</summary>
/// <param name="Place">The place.</param>
/// <param name="Loaded">Loaded blocks (the chosen one first).</param>
/// <param name="Unloaded">Neighbouring blocks the cell database has no Landblock record for (load hints).</param>
/// <param name="Buildings">Buildings in the scene.</param>
/// <param name="Kept">Kept env cells by reason.</param>
/// <param name="Hints">Unloaded env cells by reason.</param>
/// <param name="Work">The containers' work (both databases), after the extraction.</param>
public sealed record ExtractionReport(
    ScenePlace Place,
    IReadOnlyList<LandblockId> Loaded,
    IReadOnlyList<LandblockId> Unloaded,
    int Buildings,
    IReadOnlyDictionary<KeepReason, int> Kept,
    IReadOnlyDictionary<HintReason, int> Hints,
    string Work)
{
    /// <summary>Gets the number of env cells kept.</summary>
    public int KeptCells => Kept.Values.Sum();

    /// <summary>Summarises the extraction on one line.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => string.Create(
        CultureInfo.InvariantCulture,
        $"{Place}: kept {KeptCells} env cells ({Kept.GetValueOrDefault(KeepReason.Door)} behind a door, {Kept.GetValueOrDefault(KeepReason.Near)} near the point, {Kept.GetValueOrDefault(KeepReason.Block)} in the chosen block, {Kept.GetValueOrDefault(KeepReason.Portal)} through a portal); "
        + $"{Loaded.Count} loaded blocks, {Unloaded.Count} unloaded (no Landblock record); {Buildings} buildings; load hints: {Hints.Values.Sum()} cells ({Hints.GetValueOrDefault(HintReason.Missing)} not in the file, {Hints.GetValueOrDefault(HintReason.Cut)} over the cell limit, {Hints.GetValueOrDefault(HintReason.Unreached)} not reachable from the place)");
}

/// <summary>An extracted scene, the manifest the record reader read it through, and the report.</summary>
/// <param name="Scene">The scene.</param>
/// <param name="Manifest">The manifest (records, blocks, hints) handed to <see cref="DatSceneReader"/>.</param>
/// <param name="Report">What was kept and why.</param>
public sealed record ExtractedScene(Scene Scene, DatManifest Manifest, ExtractionReport Report);

/// <summary>
/// Builds the scene a walk at a place needs from a dat world (docs/dat-container.md "Scenes from a dat world"): the
/// chosen block and its neighbours (loaded when the cell database holds their Landblock record, else unloaded: load
/// hints), every building of a loaded block, the env cells reachable through portals from the place (behind the doors,
/// near the point or in the chosen block), and every other cell a kept cell or door names as an unloaded cell. The
/// records are read by the one record reader (<see cref="DatSceneReader"/>): no second geometry path.
/// </summary>
public static class SceneExtraction
{
    /// <summary>The most env cells an extraction keeps by default.</summary>
    public const int DefaultMaxCells = 1024;

    /// <summary>Extracts the scene of a place.</summary>
    /// <param name="world">The dat world.</param>
    /// <param name="place">The place.</param>
    /// <param name="maxCells">The most env cells to keep (1..<see cref="SceneRules.MaxItems"/>).</param>
    /// <returns>The scene, manifest and report.</returns>
    /// <exception cref="ArgumentException">The cell database has no Landblock record of the chosen block.</exception>
    /// <exception cref="DatContainerException">A container or a record in it cannot be read (the record reader's refusal included).</exception>
    public static ExtractedScene Extract(DatWorld world, ScenePlace place, int maxCells = DefaultMaxCells)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxCells, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(maxCells, SceneRules.MaxItems);
        if (!world.Cell.Contains(LandblockRecordId(place.Block)))
        {
            throw new ArgumentException($"{world.Cell.Name} holds no Landblock record {RecordIds.Text(LandblockRecordId(place.Block))}", nameof(place));
        }

        return new Extraction(world, place, maxCells).Run();
    }

    /// <summary>The id of a block's Landblock record.</summary>
    /// <param name="block">The block.</param>
    /// <returns>0xAABBFFFF.</returns>
    public static uint LandblockRecordId(LandblockId block) => ((uint)block.Value << 16) | 0xFFFF;

    private sealed class Extraction(DatWorld world, ScenePlace place, int maxCells)
    {
        private readonly Dictionary<LandblockId, bool> hasObjects = [];
        private readonly Dictionary<LandblockId, (LandblockInfoRecord Info, byte[] Bytes)> infos = [];
        private readonly Dictionary<uint, (EnvCellRecord Record, byte[] Bytes)> cells = [];
        private readonly List<uint> kept = [];
        private readonly HashSet<uint> keptSet = [];
        private readonly Dictionary<KeepReason, int> keptBy = [];
        private readonly SortedDictionary<uint, HintReason> hints = [];
        private readonly Queue<uint> queue = new();

        public ExtractedScene Run()
        {
            var (loaded, unloaded) = Blocks();
            foreach (var b in loaded)
            {
                ReadBlock(b);
            }

            Seed(loaded);
            while (queue.Count > 0)
            {
                uint id = queue.Dequeue();
                foreach (var p in CellOf(id).Record.Portals.Where(p => p.OtherCellId != CellPortal.Outside))
                {
                    Offer(Same(id, p.OtherCellId), KeepReason.Portal);
                }
            }

            // Everything a kept cell or a door names must be known to the scene: unloaded cells (load hints).
            foreach (uint id in kept.ToList())
            {
                var r = CellOf(id).Record;
                foreach (uint named in r.Portals.Where(p => p.OtherCellId != CellPortal.Outside).Select(p => Same(id, p.OtherCellId)).Concat(r.VisibleCells.Select(v => Same(id, v))))
                {
                    Hint(named, HintReason.Unreached);
                }
            }

            foreach (var b in loaded.Where(Readable))
            {
                foreach (var door in infos[b].Info.Buildings.SelectMany(x => x.Portals))
                {
                    Hint(((uint)b.Value << 16) | door.OtherCellId, HintReason.Unreached);
                }
            }

            var manifest = Manifest(loaded, unloaded);
            var scene = ReadScene(manifest);
            var report = new ExtractionReport(
                place,
                loaded,
                unloaded,
                scene.Buildings.Count,
                keptBy,
                hints.Values.GroupBy(h => h).ToDictionary(g => g.Key, g => g.Count()),
                $"cell: {world.Cell.Work}; portal: {world.Portal.Work}");
            return new ExtractedScene(scene, manifest, report);
        }

        private (List<LandblockId> Loaded, List<LandblockId> Unloaded) Blocks()
        {
            var loaded = new List<LandblockId> { place.Block };
            var unloaded = new List<LandblockId>();
            var around = new List<LandblockId>();
            for (int dx = -1; dx <= 1; dx++)
            {
                for (int dy = -1; dy <= 1; dy++)
                {
                    int x = place.Block.X + dx, y = place.Block.Y + dy;
                    if ((dx, dy) != (0, 0) && x is >= 0 and <= LandDefs.MaxBlockByte && y is >= 0 and <= LandDefs.MaxBlockByte)
                    {
                        around.Add(new LandblockId((byte)x, (byte)y));
                    }
                }
            }

            foreach (var b in around.OrderBy(b => b.Value))
            {
                (world.Cell.Contains(LandblockRecordId(b)) ? loaded : unloaded).Add(b);
            }

            return (loaded, unloaded);
        }

        private void ReadBlock(LandblockId b)
        {
            uint id = LandblockRecordId(b);
            var bytes = world.Cell.Read(id);
            if (bytes.Length < 8 || BitConverter.ToUInt32(bytes, 0) != id)
            {
                throw Refused(world.Cell, id, $"a Landblock record of {bytes.Length} bytes that does not start with its id");
            }

            // Terrain and heights are not part of a scene: only hasObjects is kept (ACE reads LandblockInfo only when it is 1).
            hasObjects[b] = BitConverter.ToUInt32(bytes, 4) == 1;
            uint infoId = id - 1;
            var info = world.Cell.TryRead(infoId);
            if (info is not null)
            {
                infos[b] = (Parse(world.Cell, infoId, () => LandblockInfoRecord.Read(info, infoId)), info);
            }
        }

        private bool Readable(LandblockId b) => hasObjects[b] && infos.ContainsKey(b);

        private void Seed(List<LandblockId> loaded)
        {
            foreach (var b in loaded.Where(Readable))
            {
                foreach (var building in infos[b].Info.Buildings)
                {
                    if (place.WholeBlock || Near(b, building.Origin))
                    {
                        foreach (var door in building.Portals)
                        {
                            Offer(((uint)b.Value << 16) | door.OtherCellId, KeepReason.Door);
                        }
                    }
                }
            }

            if (place.WholeBlock)
            {
                foreach (uint id in CellIds(place.Block))
                {
                    Offer(id, KeepReason.Block);
                }

                return;
            }

            foreach (var b in loaded)
            {
                foreach (uint id in CellIds(b).Where(id => Near(b, CellOf(id).Record.Origin)))
                {
                    Offer(id, KeepReason.Near);
                }
            }
        }

        private bool Near(LandblockId b, System.Numerics.Vector3 origin)
        {
            float x = origin.X + (LandDefs.BlockLength * (b.X - place.Block.X)) - place.X;
            float y = origin.Y + (LandDefs.BlockLength * (b.Y - place.Block.Y)) - place.Y;
            return (x * x) + (y * y) <= place.Radius * place.Radius;
        }

        private IEnumerable<uint> CellIds(LandblockId b)
        {
            uint count = infos.TryGetValue(b, out var i) ? Math.Min(i.Info.NumCells, LandDefs.LastEnvCellId - LandDefs.FirstEnvCellId + 1u) : 0;
            for (uint low = LandDefs.FirstEnvCellId; low < LandDefs.FirstEnvCellId + count; low++)
            {
                uint id = ((uint)b.Value << 16) | low;
                if (world.Cell.Contains(id))
                {
                    yield return id;
                }
            }
        }

        private bool Exists(uint id)
        {
            var b = new LandblockId((ushort)(id >> 16));
            uint low = id & 0xFFFF;
            return low is >= LandDefs.FirstEnvCellId and <= LandDefs.LastEnvCellId
                && infos.TryGetValue(b, out var i) && low < LandDefs.FirstEnvCellId + i.Info.NumCells && world.Cell.Contains(id);
        }

        private void Offer(uint id, KeepReason why)
        {
            if (keptSet.Contains(id))
            {
                return;
            }

            if (!Exists(id))
            {
                Hint(id, HintReason.Missing);
                return;
            }

            if (kept.Count >= maxCells)
            {
                hints[id] = HintReason.Cut;
                return;
            }

            CellOf(id);
            kept.Add(id);
            keptSet.Add(id);
            keptBy[why] = keptBy.GetValueOrDefault(why) + 1;
            queue.Enqueue(id);
        }

        private void Hint(uint id, HintReason why)
        {
            if (!keptSet.Contains(id) && !hints.ContainsKey(id))
            {
                hints[id] = Exists(id) ? why : HintReason.Missing;
            }
        }

        private (EnvCellRecord Record, byte[] Bytes) CellOf(uint id)
        {
            if (!cells.TryGetValue(id, out var c))
            {
                var bytes = world.Cell.Read(id);
                c = (Parse(world.Cell, id, () => EnvCellRecord.Read(bytes, id)), bytes);
                cells[id] = c;
            }

            return c;
        }

        private DatManifest Manifest(List<LandblockId> loaded, List<LandblockId> unloaded)
        {
            var environments = kept.Select(id => 0x0D000000u | CellOf(id).Record.EnvironmentId).Distinct().Order();
            var records = new List<ManifestRecord>();
            records.AddRange(environments.Select(id => new ManifestRecord(id, true, RecordType.Environment)));
            records.AddRange(loaded.Select(b => new ManifestRecord(LandblockRecordId(b), false, RecordType.Landblock)));
            records.AddRange(loaded.Where(Readable).Select(b => new ManifestRecord(LandblockRecordId(b) - 1, false, RecordType.LandblockInfo)));
            records.AddRange(kept.Order().Select(id => new ManifestRecord(id, false, RecordType.EnvCell)));
            return new DatManifest($"{place} from {Path.GetFileName(world.Cell.Name)}", Path.GetFileName(world.Cell.Name), records, loaded, unloaded, [.. hints.Keys.Select(id => new CellId(id))], []);
        }

        private Scene ReadScene(DatManifest manifest)
        {
            ManifestRecord? last = null;
            try
            {
                return DatSceneReader.Read(manifest, r =>
                {
                    last = r;
                    var b = new LandblockId((ushort)(r.Id >> 16));
                    return r.Type switch
                    {
                        RecordType.Environment => world.Portal.Read(r.Id),
                        RecordType.Landblock => LandblockRecord.WriteFlat(r.Id, hasObjects[b]),
                        RecordType.LandblockInfo => infos[b].Bytes,
                        _ => CellOf(r.Id).Bytes,
                    };
                });
            }
            catch (InputFormatException e)
            {
                var container = last?.PortalDat == true ? world.Portal : world.Cell;
                throw Refused(container, last?.Id, e.Message, e);
            }
        }

        private static T Parse<T>(DatContainer container, uint id, Func<T> read)
        {
            try
            {
                return read();
            }
            catch (InputFormatException e)
            {
                throw Refused(container, id, e.Message, e);
            }
        }

        private static DatContainerException Refused(DatContainer container, uint? id, string message, Exception? inner = null)
        {
            long offset = id is { } x && container.TryGetEntry(x, out var entry) ? entry.Offset : 0;
            return new DatContainerException(container.Name, id, offset, "the record reader refuses it: " + message, inner);
        }

        private static uint Same(uint cell, ushort low) => (cell & 0xFFFF0000) | low;
    }
}
