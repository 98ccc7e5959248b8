using AcPhys.Core;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Judging;

/// <summary>
/// The statements a declared deviation breaks by design (issue 27, "no false alarm from the reference in every declared
/// mode"): a port that declares the switch and serves it faithfully fails them however correct it is, so they are NOT
/// TESTED under that switch, with the switch named. Asked for every invariant by <see cref="Invariant.WhyNotTestable(ICellPhysics)"/>,
/// so <see cref="Judges"/> and the catalogue runner agree. Only what the declaration changes: a port that serves a
/// deviation while declaring retail is judged on every statement, and the conformance invariants compare in the
/// declared mode and are never listed here.
/// </summary>
/// <remarks>
/// One row per switch, measured on the unfaulted reference (<c>acphys verify --cases 1000 --fidelity SWITCH</c>, pr base
/// seed; docs/facts-coverage.md, "No false alarm from the reference") and each row's invariants checked against the ACE
/// difference it names in facts §7 (and §4, where the step is described). Switches that break nothing have no row:
/// ace-filter-outside-guard, ace-outside-by-cell-id, ace-no-portal-guard (the oracles honour it,
/// <see cref="SceneOracle.Pickable"/>), drop-unloaded-land-cells, ace-transition-filter, reframe-transit and double.
/// </remarks>
public static class BrokenByDesign
{
    private static readonly Row[] Table =
    [
        // §7 #6, §4 step 1: ACE does not clear the array, so earlier queries' cells stay candidates (out of the body's
        // reach, unseen from the position, picked as the containing cell, again after the scene moved by a block), and
        // a cell already held is not appended again where retail's walk would reach it.
        new("ace-keeps-stale-cells", "§7 #6, §4 step 1: the array is not cleared between calls", ["PORTAL-TRANSIT", "NO-TUNNEL", "VISIBILITY", "SCENE-TRANSLATION", "NEVER-NULL", "SCENE-SOUNDNESS", "ENV-CANDIDATE-JUSTIFIED"]),

        // §7 #7, §4 steps 4b and 5: after an interior pick ACE returns before the visibility filter, so land cells and
        // cells the position does not see stay candidates of a static query.
        new("ace-early-return", "§7 #7, §4 step 5: an interior pick returns before the visibility filter", ["VISIBILITY"]),

        // §7 #10, §5.1: a portal neighbour missing from the cell's VisibleCells is not resolved but added as a load hint,
        // a null entry under the id of a loaded cell the position does not see, and the filter keeps null entries.
        new("ace-neighbour-via-visible-cells", "§7 #10, §5.1: a neighbour the cell does not see is added as a load hint", ["VISIBILITY"]),

        // §7 #11, §5.1: a load hint is keyed by the bare 16-bit id: not the full id of a portal target, not moved with
        // the scene, not the id the position's portal names.
        new("ace-load-hint-low-key", "§7 #11, §5.1: load hints carry the 16-bit id, not the full id", ["PORTAL-TRANSIT", "SCENE-TRANSLATION", "SCENE-SOUNDNESS"]),
    ];

    /// <summary>Gets every (switch, invariant) pair the table exempts, in table order.</summary>
    public static IReadOnlyList<(string Switch, string InvariantId)> Exempted { get; } =
        [.. Table.SelectMany(r => r.Invariants.Select(id => (r.Switch, id)))];

    /// <summary>Says why an invariant is not judged under a declared mode, or null when it is.</summary>
    /// <param name="invariantId">The invariant.</param>
    /// <param name="indoor">The declared indoor deviations.</param>
    /// <param name="outdoor">The declared outdoor deviations.</param>
    /// <returns>The reason naming every declared switch that breaks it, or null.</returns>
    public static string? WhyNotJudged(string invariantId, IndoorFidelity indoor, OutdoorFidelity outdoor)
    {
        var declared = FidelityNames.Names(indoor, outdoor);
        if (declared.Count == 0)
        {
            return null; // retail declared: every statement is judged
        }

        var rows = Table.Where(r => declared.Contains(r.Switch) && r.Invariants.Contains(invariantId, StringComparer.Ordinal)).ToList();
        if (rows.Count == 0)
        {
            return null;
        }

        string what = InvariantScope.Of(invariantId)?.Scope == Scope.Retail ? "a retail statement" : "a statement";
        string switches = string.Join(", ", rows.Select(r => r.Switch));
        string facts = string.Join("; ", rows.Select(r => r.Facts));
        return $"{what} the declared {switches} {(rows.Count == 1 ? "breaks" : "break")} by design (facts {facts})";
    }

    private sealed record Row(string Switch, string Facts, IReadOnlyList<string> Invariants);
}
