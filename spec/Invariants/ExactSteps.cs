using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// What the exact indoor invariants share about one query: the walk run in both modes, the frame a transit test puts
/// a sphere centre in, whether the static visibility filter may have removed a cell, which entries were walked, and
/// the 1 mm thresholds on the BSP sphere test.
/// </summary>
internal static class ExactSteps
{
    /// <summary>The BSP sphere test's radius padding (facts §5.7, BN:222), not EPS.</summary>
    public const double BspPadding = 0.01;

    /// <summary>
    /// Checks every step of the walk in each kind of scene query the implementation offers: static placement, movement
    /// transition (facts §6.14), or both (<see cref="SceneQueryKinds"/>); the first violation wins, else Holds when some step applied.
    /// </summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="w">The scene walk.</param>
    /// <param name="check">One step's check.</param>
    /// <returns>The outcome; a violation's message starts with <c>step N:</c>.</returns>
    public static Outcome EachStep(ICellPhysics impl, SceneWalk w, Func<ExactScene, WalkStep, Outcome> check)
    {
        var scene = ExactScene.Of(w.Scene);
        bool applied = false;
        string? why = null;
        foreach (bool loadCells in SceneQueryKinds.Offered(impl.Ops))
        {
            foreach (var s in SceneWalkRunner.Run(impl, w, loadCells))
            {
                var o = check(scene, s);
                if (o.IsViolation)
                {
                    return Outcome.ViolatedAt(s.Index, $"step {s.Index}: ({(loadCells ? "transition" : "static")} query from {s.Query.Cell}) {o.Message}");
                }

                applied |= o.Verdict == Verdict.Holds;
                why ??= o.Message;
            }
        }

        return applied ? Outcome.Holds : why is null ? Outcome.Vacuous : Outcome.VacuousBecause(why);
    }

    /// <summary>
    /// Returns a sphere centre as a transit or building test uses it for a cell: in the position's block frame with no
    /// block offset (facts §5.1, §5.3, §6.11), unless the implementation declares the re-framing deviation.
    /// </summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="position">The position's cell id.</param>
    /// <param name="cell">The cell being tested.</param>
    /// <param name="center">The centre in the position's block frame.</param>
    /// <returns>The point handed to the cell's frame.</returns>
    public static Vector3 TransitPoint(ICellPhysics impl, CellId position, CellId cell, Vector3 center) =>
        impl.Indoor.ReframeTransit ? center - LandDefs.GetBlockOffset(position, cell) : center;

    /// <summary>Tests whether some sphere intersects the cell's first piece by more than the margin under the BSP test (R = r + 0.01, facts §5.7).</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="s">The step.</param>
    /// <param name="cell">The cell.</param>
    /// <returns>True when the test must say "not Outside".</returns>
    public static bool SurelyIntersects(ICellPhysics impl, WalkStep s, ExactCell cell) =>
        s.Query.Spheres.Any(sp => cell.DepthFirst(TransitPoint(impl, s.Query.Cell, cell.Source.Id, sp.Center)) > -(sp.Radius + BspPadding) + IndoorInvariants.Margin);

    /// <summary>Tests whether some sphere comes within the margin of intersecting the cell's first piece under the BSP test (facts §5.7: not a later piece).</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="s">The step.</param>
    /// <param name="cell">The cell.</param>
    /// <returns>False when every sphere is clear of the cell by more than the margin.</returns>
    public static bool MayIntersect(ICellPhysics impl, WalkStep s, ExactCell cell) =>
        s.Query.Spheres.Any(sp => cell.DepthFirst(TransitPoint(impl, s.Query.Cell, cell.Source.Id, sp.Center)) >= -(sp.Radius + BspPadding) - IndoorInvariants.Margin);

    /// <summary>Tests whether the indoor visibility filter ran on this query (facts §4 step 5: static query from an indoor position).</summary>
    /// <param name="s">The step.</param>
    /// <returns>True when it may have removed cells.</returns>
    public static bool Filtered(WalkStep s) => !s.LoadCells && s.Query.Cell.IsIndoorByLowWord;

    /// <summary>Tests whether a loaded cell survives the visibility filter: the position itself, or a loaded env cell in the position's VisibleCells (facts §4 step 5).</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="s">The step.</param>
    /// <param name="id">A loaded cell.</param>
    /// <returns>True when the filter keeps it (always true when the filter did not run).</returns>
    public static bool SurvivesFilter(ExactScene scene, WalkStep s, CellId id) =>
        !Filtered(s) || id == s.Query.Cell || (scene.Env(s.Query.Cell) is { } own && own.Source.Visible.Contains(id) && scene.Env(id) is not null);

    /// <summary>
    /// Tests whether candidate <paramref name="i"/> is a loaded entry (so the closure walked it and the pick tested it):
    /// reported loaded (or no flags reported) and loaded in the scene.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="s">The step.</param>
    /// <param name="i">Index into the candidates.</param>
    /// <returns>True when loaded.</returns>
    public static bool IsLoadedEntry(ExactScene scene, WalkStep s, int i)
    {
        var id = s.Cells[i];
        bool declared = id.IsLand ? scene.IsLoadedLand(id) : scene.Env(id) is not null;
        return declared && (s.Answer?.Loaded is not { } flags || (i < flags.Count && flags[i]));
    }
}
