using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Scenes;

namespace AcPhys.Formats.Dat.Container;

/// <summary>
/// Writes scenes as a dat world: their records (<see cref="DatSceneWriter"/>) split into a cell and a portal container
/// (<see cref="DatContainerWriter"/>). Several scenes go in as one union scene (one Environment holds every geometry), so
/// their blocks and cells must not collide; a scene given twice is written once.
/// </summary>
public static class SceneContainers
{
    /// <summary>Builds the records of scenes, cell-dat and portal-dat apart.</summary>
    /// <param name="scenes">The scenes.</param>
    /// <returns>The cell-dat and portal-dat objects.</returns>
    /// <exception cref="ArgumentException">Two different scenes share a loaded block.</exception>
    public static (List<(uint Id, byte[] Bytes)> Cell, List<(uint Id, byte[] Bytes)> Portal) Records(IEnumerable<Scene> scenes)
    {
        var export = DatSceneWriter.Write(Union(scenes), "union", "union");
        return (
            [.. export.Records.Where(r => !r.Record.PortalDat).Select(r => (r.Record.Id, r.Bytes))],
            [.. export.Records.Where(r => r.Record.PortalDat).Select(r => (r.Record.Id, r.Bytes))]);
    }

    /// <summary>Writes scenes as a cell and a portal container.</summary>
    /// <param name="scenes">The scenes.</param>
    /// <param name="cellPath">The cell database to write.</param>
    /// <param name="portalPath">The portal database to write.</param>
    /// <param name="blockSize">The block size of both.</param>
    /// <returns>The number of objects in each.</returns>
    public static (int Cell, int Portal) Write(IEnumerable<Scene> scenes, string cellPath, string portalPath, uint blockSize = 1024)
    {
        var (cell, portal) = Records(scenes);
        return (DatContainerWriter.Write(cellPath, cell, DatSet.Cell, blockSize), DatContainerWriter.Write(portalPath, portal, DatSet.Portal, blockSize));
    }

    /// <summary>The union of scenes: loaded blocks, buildings and cells of all; a block loaded by one is not unloaded in the union.</summary>
    /// <param name="scenes">The scenes.</param>
    /// <returns>The union.</returns>
    /// <exception cref="ArgumentException">Two different scenes share a loaded block.</exception>
    public static Scene Union(IEnumerable<Scene> scenes)
    {
        var distinct = scenes.DistinctBy(SceneJson.WriteCompact).ToList();
        var owner = new Dictionary<LandblockId, int>();
        for (int i = 0; i < distinct.Count; i++)
        {
            foreach (var b in distinct[i].Blocks)
            {
                if (!owner.TryAdd(b, i))
                {
                    throw new ArgumentException($"block {b} is loaded by two different scenes ({owner[b]} and {i}); a union cannot hold both", nameof(scenes));
                }
            }
        }

        var cells = distinct.SelectMany(s => s.Cells).ToList();
        var cellIds = cells.Select(c => c.Id).ToHashSet();
        return new Scene([.. owner.Keys], [.. distinct.SelectMany(s => s.Buildings)], cells)
        {
            UnloadedBlocks = [.. distinct.SelectMany(s => s.UnloadedBlocks).Distinct().Where(b => !owner.ContainsKey(b))],
            UnloadedCells = [.. distinct.SelectMany(s => s.UnloadedCells).Distinct().Where(c => !cellIds.Contains(c))],
        };
    }
}
