using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Parts held in another env cell than the anchor's (issue 53): for some non-anchor parts still held in the anchor's
/// cell, the part's Position names a portal neighbour of that cell in the same block (its frame unchanged: one block
/// frame), or an env cell of another block with its origin re-based by the block offset, so its world position is
/// unchanged (facts §3.4, §5.2, §5.8: a part's frame is in its own cell's block, and LocalToLocal applies
/// GetBlockOffset). The physics must answer as if the part were held in the anchor's cell.
/// </summary>
internal static class PartCells
{
    /// <summary>Returns whether part <paramref name="k"/> at a step is held in a portal neighbour of its cell: 1 in 4 non-anchor parts.</summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index (the anchor, 0, never).</param>
    /// <returns>True to hold it in a neighbour.</returns>
    public static bool InNeighbour(int step, int k) => k > 0 && ((step + k) & 3) == 0;

    /// <summary>Returns whether part <paramref name="k"/> at a step is held in an env cell of another block: 1 in 4 non-anchor parts (never one <see cref="PartFrames.Across"/> re-frames).</summary>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index (the anchor, 0, never).</param>
    /// <returns>True to hold it in another block's env cell.</returns>
    public static bool InOtherBlock(int step, int k) => k > 0 && ((step + k) & 3) == 2;

    /// <summary>Re-holds a part in another env cell when <see cref="InNeighbour"/> or <see cref="InOtherBlock"/> picks it and it is still held in the anchor's cell.</summary>
    /// <param name="scene">The scene as given (its cells, for another block's).</param>
    /// <param name="built">The scene built (neighbours and buildings).</param>
    /// <param name="step">The step index.</param>
    /// <param name="k">The part's index.</param>
    /// <param name="anchorCell">The anchor's cell (the position's).</param>
    /// <param name="part">The part.</param>
    /// <returns>The part, held in another env cell or unchanged.</returns>
    public static Part Hold(Scene scene, CellScene built, int step, int k, CellId anchorCell, Part part)
    {
        if (part.Cell != anchorCell)
        {
            return part; // already held across a block line (PartFrames)
        }

        if (InNeighbour(step, k))
        {
            var near = Neighbours(built, anchorCell);
            return near.Count == 0 ? part : part with { Cell = near[(step / 4) % near.Count] };
        }

        if (InOtherBlock(step, k))
        {
            var other = OtherBlockCell(scene, anchorCell, step);
            return part with { Cell = other, Frame = part.Frame with { Origin = part.Frame.Origin + LandDefs.GetBlockOffset(other, anchorCell) } };
        }

        return part;
    }

    // A loaded env cell's portal neighbours the scene has, or a land cell's building's doors' env cells (same block, §5.3).
    private static List<CellId> Neighbours(CellScene built, CellId cell)
    {
        var near = new List<CellId>();
        if (cell.IsEnv && built.GetEnvCell(cell) is { } env)
        {
            foreach (var portal in env.Portals)
            {
                var id = cell.WithLow(portal.OtherCellId);
                if (portal.OtherCellId != CellPortal.Outside && id != cell && built.GetEnvCell(id) is not null && !near.Contains(id))
                {
                    near.Add(id);
                }
            }
        }
        else if (cell.IsLand && built.GetBuilding(cell) is { } building)
        {
            foreach (var door in building.Portals)
            {
                var id = cell.WithLow(door.OtherCellId);
                if (built.GetEnvCell(id) is not null && !near.Contains(id))
                {
                    near.Add(id);
                }
            }
        }

        return near;
    }

    // An env cell of the scene in another block than the anchor's, else the first env cell of the block east (west at the map's edge).
    private static CellId OtherBlockCell(Scene scene, CellId anchor, int step)
    {
        var others = scene.Cells.Select(c => c.Id).Where(id => id.IsEnv && id.Landblock != anchor.Landblock).ToArray();
        if (others.Length > 0)
        {
            return others[(step / 4) % others.Length];
        }

        int bx = anchor.BlockX < 0xFE ? anchor.BlockX + 1 : anchor.BlockX - 1;
        return new CellId((byte)bx, anchor.BlockY, LandDefs.FirstEnvCellId);
    }
}
