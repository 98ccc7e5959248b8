namespace AcPhys.Spec.Invariants;

/// <summary>
/// The retail / hardening label of every catalogue invariant (issue #18, build item 4), with the facts section a retail
/// invariant rests on or the reason a hardening rule exists. Criterion: retail when every retail-exact answer satisfies
/// the invariant (tolerance bands only weaken it); hardening when a retail-exact port can fail it.
/// </summary>
public static class InvariantScope
{
    // Non-finite points are asked (an exception is a violation) but judged only by the hardening rules (facts §6.17).
    private const string FiniteOnly = "; non-finite points judged only by NONFINITE-REJECTED (facts §6.17)";

    private static readonly Dictionary<string, (Scope Scope, string Reason)> Table = new(StringComparer.Ordinal)
    {
        ["LCOORD-ROUNDTRIP"] = (Scope.Retail, "facts §1.2, §1.3, §2"),
        ["LCOORD-BLOCK"] = (Scope.Retail, "facts §1.3, §2 (id 0 excluded: ACE and retail differ, §7 #16)"),
        ["OUTSIDE-LCOORD-GEOMETRY"] = (Scope.Retail, "facts §2 get_outside_lcoord, §6.2" + FiniteOnly),
        ["ADJUST-GEOMETRY"] = (Scope.Retail, "facts §2.1, §6.3, §6.4" + FiniteOnly),
        ["ADJUST-IDEMPOTENT"] = (Scope.Retail, "facts §2.1" + FiniteOnly),
        ["ADJUST-PRESERVES-POSITION"] = (Scope.Retail, "facts §2.1 step 4" + FiniteOnly),
        ["ADJUST-RANGE"] = (Scope.Retail, "facts §2.1 (re-based point in [0, 192))" + FiniteOnly),
        ["MAP-EDGE"] = (Scope.Retail, "facts §1.3, §6.3"),
        ["NONFINITE-REJECTED"] = (Scope.Hardening, "rejecting NaN/Inf protects a port from NaN becoming a valid cell; retail has no finiteness test (facts §6.17)"),
        ["NONFINITE-SPHERE-ENDS-LOOP"] = (Scope.Hardening, "a non-finite centre ends the sphere loop as an off-map one does, so NaN never becomes a cell; retail most likely re-seats it in its block's own column (facts §6.17)"),
        ["COVERAGE"] = (Scope.Retail, "facts §3.2, §3.3 (1 mm band: weaker than retail's strict tests, not beyond them)"),
        ["SOUNDNESS"] = (Scope.Retail, "facts §3.2, §5.9 (no duplicates: retail's array de-duplicates)"),
        ["NEIGHBOUR-SYMMETRY"] = (Scope.Retail, "facts §1.3, §2.1, §6.1"),
        ["TRANSLATION"] = (Scope.Retail, "facts §1.3, §3"),
        ["SPHERE-ORDER"] = (Scope.Retail, "facts §3.3"),
        ["STABLE-PICK"] = (Scope.Retail, "facts §4 step 4b, §5.5"),
        ["HYSTERESIS"] = (Scope.Hardening, "acdream's current-cell-first pick (issue #3), not retail's last-wins pick (facts §4 step 4b): keeps jitter on a line from flipping cells; only tested on a current-first implementation"),
        ["NO-BOUNDARY-FREEZE"] = (Scope.Retail, "facts §4, §6.1 (seed #106)"),
        ["WALK-REVERSIBLE"] = (Scope.Retail, "facts §4 (the retail pick depends on the position alone)"),
        ["MAP-EDGE-WALK"] = (Scope.Retail, "facts §6.3"),
        ["PARTS-COVERAGE"] = (Scope.Retail, "facts §3.4, §7 #3"),
        ["PARTS-SOUNDNESS"] = (Scope.Retail, "facts §3.4, §5.9"),
        ["INTERIOR-WINS"] = (Scope.Retail, "facts §4 step 4b"),
        ["HYSTERESIS-INDOOR"] = (Scope.Hardening, "acdream's current-cell-first pick in scenes, not retail's pick (facts §4 step 4b): at most one switch per real crossing"),
        ["PORTAL-TRANSIT"] = (Scope.Retail, "facts §4 step 4a, §5.1, §5.3, §5.4, §6.9, §6.11"),
        ["NO-TUNNEL"] = (Scope.Retail, "facts §3.2, §5.1, §5.3"),
        ["VISIBILITY"] = (Scope.Retail, "facts §4 step 5, §6.14"),
        ["ENTER-EXIT"] = (Scope.Retail, "facts §4"),
        ["SCENE-TRANSLATION"] = (Scope.Retail, "facts §1.3, §5.8"),
        ["CONTAINING-CONTAINS"] = (Scope.Retail, "facts §4 step 4b, §5.5"),
        ["NEVER-NULL"] = (Scope.Retail, "facts §4 step 4b, §5.1, §6.3, §6.9 (every retail null case is an excused reason)"),
        ["SCENE-SOUNDNESS"] = (Scope.Retail, "facts §3.2, §4 step 1, §5.1, §5.3, §5.7, §6.13 (retail truncates the array, §7 #6)"),
        ["NEIGHBOURS-COMPLETE"] = (Scope.Retail, "facts §4 step 4a, §5.1, §5.7, §6.10"),
        ["BUILDING-ENTRY-COMPLETE"] = (Scope.Retail, "facts §4 step 4a, §5.3, §5.7, §6.11"),
        ["ENV-CANDIDATE-JUSTIFIED"] = (Scope.Retail, "facts §4 step 4a, §5.1, §5.3, §5.7"),
        ["HITS-INTERIOR"] = (Scope.Retail, "facts §1.1, §4 steps 3 and 4b, §5.3"),
        ["LAND-VIA-EXIT"] = (Scope.Retail, "facts §3.3, §5.1, §6.9"),
        ["PICK-FIRST-ENV"] = (Scope.Retail, "facts §4 step 4b, §5.5, §5.7, §6.8"),
        ["TIES-PINNED-INDOOR"] = (Scope.Retail, "facts §1.5, §5.1, §5.3, §5.4, §5.7, §6.10"),
        ["PARTS-INDOOR-SOUNDNESS"] = (Scope.Retail, "facts §3.4, §4 step 5, §5.2, §5.3, §5.9 (1 mm band)"),
        ["PARTS-INDOOR-COVERAGE"] = (Scope.Retail, "facts §4 step 4a, §5.2, §5.4, §5.7 (1 mm band: weaker than retail's tests, not beyond them)"),
        ["PARTS-BUILDING-ENTRY"] = (Scope.Retail, "facts §5.3, §5.8 (1 mm band)"),
        ["PARTS-INDOOR-CONFORMANCE"] = (Scope.Retail, "facts §3.4, §4, §5.2, §5.3 (the retail-faithful reference in the declared mode)"),
        ["LANDDEFS-CONFORMANCE"] = (Scope.Retail, "facts §1, §2 (the retail-faithful reference)" + FiniteOnly),
        ["OUTSIDE-CELLS-CONFORMANCE"] = (Scope.Retail, "facts §3.1–§3.3 (the retail-faithful reference); non-finite centres judged only by NONFINITE-SPHERE-ENDS-LOOP (facts §6.17)"),
        ["FIND-CELL-QUERY-CONFORMANCE"] = (Scope.Retail, "facts §3.2, §3.3, §4, §6.5, §6.7, §6.12 (the retail-faithful reference); non-finite centres judged only by NONFINITE-SPHERE-ENDS-LOOP (facts §6.17)"),
        ["FIND-CELL-CONFORMANCE"] = (Scope.Retail, "facts §3, §4, §5 (the retail-faithful reference in the declared mode)"),
    };

    /// <summary>Gets the IDs that carry a label.</summary>
    public static IReadOnlyCollection<string> LabelledIds => Table.Keys;

    /// <summary>Returns the label of an invariant, or null when it has none.</summary>
    /// <param name="id">The invariant ID.</param>
    /// <returns>The scope and its facts section or reason, or null.</returns>
    public static (Scope Scope, string Reason)? Of(string id) => Table.TryGetValue(id, out var label) ? label : null;

    /// <summary>Returns the lower-case name of a scope (retail, hardening).</summary>
    /// <param name="scope">The scope.</param>
    /// <returns>The name.</returns>
    public static string Name(Scope scope) => scope == Scope.Retail ? "retail" : "hardening";
}
