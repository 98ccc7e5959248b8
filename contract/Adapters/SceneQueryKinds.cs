namespace AcPhys.Contract;

/// <summary>
/// The two kinds of scene query a port may offer, alone or both (issue #29): static placement
/// (<see cref="Op.FindCellScene"/>, LoadCells false: the indoor visibility filter runs, facts §4 step 5) and the
/// movement transition (<see cref="Op.FindCellTransition"/>, LoadCells true: it does not, facts §6.14). A port whose
/// cell query is called only from its transition code offers the second alone and is gated on transitions.
/// </summary>
public static class SceneQueryKinds
{
    /// <summary>Either scene query: an implementation offering one of them is tested on scenes.</summary>
    public const Op Either = Op.FindCellScene | Op.FindCellTransition;

    /// <summary>Tests whether an implementation offers some scene query.</summary>
    /// <param name="ops">The implementation's operations.</param>
    /// <returns>True when it answers scenes in at least one kind.</returns>
    public static bool OffersScenes(Op ops) => (ops & Either) != 0;

    /// <summary>
    /// Returns the kinds an implementation offers as LoadCells values, static first: [false], [true] or [false, true]
    /// (empty when it offers neither).
    /// </summary>
    /// <param name="ops">The implementation's operations.</param>
    /// <returns>The LoadCells value of each kind offered.</returns>
    public static IReadOnlyList<bool> Offered(Op ops) =>
        ((ops & Op.FindCellScene) != 0, (ops & Op.FindCellTransition) != 0) switch
        {
            (true, true) => [false, true],
            (true, false) => [false],
            (false, true) => [true],
            _ => [],
        };

    /// <summary>
    /// Returns the kind an invariant stated for either kind asks in: static placement when offered (as every scene
    /// invariant asked before transition-only ports existed, so their verdicts are unchanged), else the transition.
    /// </summary>
    /// <param name="ops">The implementation's operations.</param>
    /// <returns>The LoadCells value: false for static placement, true for a transition.</returns>
    public static bool Primary(Op ops) => (ops & Op.FindCellScene) == 0 && (ops & Op.FindCellTransition) != 0;
}
