using System.Numerics;
using AcPhys.Core;
using AcPhys.Spec.Adapters;

namespace AcPhys.Spec.Cases;

/// <summary>What happened at one step of a walk.</summary>
/// <param name="Index">0 for the start query, then 1..n.</param>
/// <param name="Frame">The cell id whose block frame <paramref name="Position"/> is in (the cell passed to find_cell).</param>
/// <param name="Position">Block-frame position before re-framing.</param>
/// <param name="WorldX">The position in world metres: 192·bx of <paramref name="Frame"/> + the client's float32 position, exact in double.</param>
/// <param name="WorldY">As <paramref name="WorldX"/>.</param>
/// <param name="Query">The find_cell query that was asked.</param>
/// <param name="Cells">The candidate cells answered.</param>
/// <param name="Containing">The containing cell answered (<see cref="CellId.None"/> when none).</param>
/// <param name="Current">The current cell after the step (kept when the answer was none).</param>
public sealed record WalkStep(int Index, CellId Frame, Vector3 Position, double WorldX, double WorldY, OutdoorCase Query, IReadOnlyList<CellId> Cells, CellId Containing, CellId Current)
{
    /// <summary>Gets the whole answer (load-hint flags and HitsInteriorCell as reported), or null for records made by hand.</summary>
    public FindCellResult? Answer { get; init; }

    /// <summary>Gets a value indicating whether the step was asked as a movement transition (LoadCells true: no visibility filter).</summary>
    public bool LoadCells { get; init; }
}

/// <summary>
/// Runs a walk against an implementation as a client does: the current cell is threaded through find_cell step by
/// step; after each answer the position is re-framed into the containing cell's block (GetBlockOffset). When the
/// answer is none, the client keeps its current cell and frame (that is what a freeze looks like).
/// </summary>
public static class WalkRunner
{
    /// <summary>Runs the walk.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="walk">The walk.</param>
    /// <returns>One record for the start query and one per step.</returns>
    public static IReadOnlyList<WalkStep> Run(ICellPhysics impl, Walk walk)
    {
        var steps = new List<WalkStep>(walk.Steps.Count + 1);
        var frame = walk.StartCell;
        var position = walk.Start;
        var current = CellId.None;
        for (int i = 0; i <= walk.Steps.Count; i++)
        {
            if (i > 0)
            {
                var d = walk.Steps[i - 1];
                position += new Vector3(d.X, d.Y, 0);
            }

            // The world point of the position the client holds (float32 drift included): re-framing preserves it.
            double worldX = (192.0 * frame.BlockX) + position.X, worldY = (192.0 * frame.BlockY) + position.Y;

            var query = new OutdoorCase(frame, walk.SpheresAt(position)) { Origin = position };
            var answer = impl.FindCell(frame, position, query.Spheres, current);
            var before = position;
            if (!answer.Containing.IsNone)
            {
                position -= LandDefs.GetBlockOffset(frame, answer.Containing);
                frame = answer.Containing;
                current = answer.Containing;
            }

            steps.Add(new WalkStep(i, query.Cell, before, worldX, worldY, query, answer.Cells, answer.Containing, current) { Answer = answer });
        }

        return steps;
    }
}
