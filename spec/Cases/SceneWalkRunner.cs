using System.Numerics;
using AcPhys.Core;
using AcPhys.Spec.Adapters;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Runs a walk in a scene as a client does (as <see cref="WalkRunner"/> on open land): the current cell is threaded
/// through find_cell_scene and passed as the position's cell; after each answer the position is re-framed into the
/// containing cell's block (GetBlockOffset); with no answer the client keeps its cell and frame.
/// </summary>
public static class SceneWalkRunner
{
    /// <summary>Runs the walk.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="sw">The scene walk.</param>
    /// <param name="loadCells">True to ask each step as a movement transition (no visibility filter, facts §6.14); the implementation must offer <see cref="Op.FindCellTransition"/>.
    /// A step's <see cref="WalkStep.LoadCells"/> says whether the filter was off: not for an implementation declaring ACE's transition filter (facts §7 #9).</param>
    /// <returns>One record for the start query and one per step.</returns>
    public static IReadOnlyList<WalkStep> Run(ICellPhysics impl, SceneWalk sw, bool loadCells = false)
    {
        var walk = sw.Walk;
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

            double worldX = (192.0 * frame.BlockX) + position.X, worldY = (192.0 * frame.BlockY) + position.Y;
            var query = new OutdoorCase(frame, walk.SpheresAt(position));
            var answer = impl.FindCell(sw.Scene, frame, query.Spheres, current, loadCells);
            var before = position;
            if (!answer.Containing.IsNone)
            {
                position -= LandDefs.GetBlockOffset(frame, answer.Containing);
                frame = answer.Containing;
                current = answer.Containing;
            }

            steps.Add(new WalkStep(i, query.Cell, before, worldX, worldY, query, answer.Cells, answer.Containing, current) { Answer = answer, LoadCells = loadCells && !impl.Indoor.AceTransitionFilters });
        }

        return steps;
    }
}
