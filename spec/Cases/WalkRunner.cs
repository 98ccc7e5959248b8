using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;

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
/// answer is none, the client keeps its current cell and frame (that is what a freeze looks like). The walk is asked
/// whole (<see cref="ICellPhysics.FindCellWalk"/>) and its answers threaded by the same rule (<see cref="WalkThread"/>).
/// </summary>
public static class WalkRunner
{
    /// <summary>Runs the walk.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="walk">The walk.</param>
    /// <returns>One record for the start query and one per step.</returns>
    public static IReadOnlyList<WalkStep> Run(ICellPhysics impl, Walk walk)
    {
        var request = Request(walk, null);
        return Trace(request, impl.FindCellWalk(request), loadCells: false);
    }

    /// <summary>Returns the walk as a whole-walk request (<see cref="ICellPhysics.FindCellWalk"/>).</summary>
    /// <param name="walk">The walk.</param>
    /// <param name="scene">The scene, or null for open land.</param>
    /// <param name="loadCells">True to ask each step as a movement transition.</param>
    /// <returns>The request.</returns>
    public static WalkRequest Request(Walk walk, AcPhys.Contract.Scene? scene, bool loadCells = false) =>
        new(scene, walk.StartCell, walk.Start, [.. walk.Body.Select(b => new Sphere(b.Offset, b.Radius))], walk.Steps) { LoadCells = loadCells };

    /// <summary>
    /// Threads a walk's answers by <see cref="WalkThread"/> into step records: each record holds the query the rule asks
    /// at that step and the answer given for it.
    /// </summary>
    /// <param name="walk">The walk asked.</param>
    /// <param name="answers">One answer per query.</param>
    /// <param name="loadCells">Whether the steps were asked as movement transitions.</param>
    /// <returns>One record for the start query and one per step.</returns>
    /// <exception cref="InvalidOperationException">The answers are not one per query (an adapter's defect).</exception>
    public static IReadOnlyList<WalkStep> Trace(WalkRequest walk, IReadOnlyList<FindCellResult> answers, bool loadCells)
    {
        if (answers.Count != walk.Queries)
        {
            throw new InvalidOperationException($"a walk of {walk.Queries} queries was answered with {answers.Count} answers");
        }

        var steps = new List<WalkStep>(walk.Queries);
        var thread = new WalkThread(walk);
        while (thread.MoveNext())
        {
            var frame = thread.Frame;
            var position = thread.Position;

            // The world point of the position the client holds (float32 drift included): re-framing preserves it.
            double worldX = (192.0 * frame.BlockX) + position.X, worldY = (192.0 * frame.BlockY) + position.Y;
            var query = new OutdoorCase(frame, thread.Spheres()) { Origin = walk.Scene is null ? position : default };
            var answer = answers[thread.Index];
            thread.Take(answer.Containing);
            steps.Add(new WalkStep(thread.Index, frame, position, worldX, worldY, query, answer.Cells, answer.Containing, thread.Current) { Answer = answer, LoadCells = loadCells });
        }

        return steps;
    }
}
