using AcPhys.Contract;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Runs a walk in a scene as a client does (as <see cref="WalkRunner"/> on open land): the current cell is threaded
/// through find_cell_scene (or find_cell_transition) and passed as the position's cell; after each answer the position is re-framed into the
/// containing cell's block (GetBlockOffset); with no answer the client keeps its cell and frame.
/// </summary>
public static class SceneWalkRunner
{
    /// <summary>
    /// Runs the walk in the kind of scene query the implementation offers: static placement when it offers it, else
    /// as movement transitions (<see cref="SceneQueryKinds.Primary"/>: a transition-only port, issue #29).
    /// </summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="sw">The scene walk.</param>
    /// <returns>One record for the start query and one per step.</returns>
    public static IReadOnlyList<WalkStep> Run(ICellPhysics impl, SceneWalk sw) => Run(impl, sw, SceneQueryKinds.Primary(impl.Ops));

    /// <summary>Runs the walk in one kind of scene query.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="sw">The scene walk.</param>
    /// <param name="loadCells">True to ask each step as a movement transition (no visibility filter, facts §6.14); the implementation must offer <see cref="Op.FindCellTransition"/>.
    /// A step's <see cref="WalkStep.LoadCells"/> says whether the filter was off: not for an implementation declaring ACE's transition filter (facts §7 #9).</param>
    /// <returns>One record for the start query and one per step.</returns>
    public static IReadOnlyList<WalkStep> Run(ICellPhysics impl, SceneWalk sw, bool loadCells) => SceneWalkMemo.Of(impl, sw, loadCells, () =>
    {
        var request = WalkRunner.Request(sw.Walk, sw.Scene, loadCells);

        // A step's LoadCells says whether the filter was off: ACE's transitions filter (facts §7 #9).
        return WalkRunner.Trace(request, impl.FindCellWalk(request), loadCells && !impl.Indoor.AceTransitionFilters);
    });
}
