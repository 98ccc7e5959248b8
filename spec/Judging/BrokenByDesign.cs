using AcPhys.Contract;
using AcPhys.Core;
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
/// difference it names in facts §7 (and §4 or §5, where the step is described). Where an oracle can honour a switch
/// it judges under it instead: ace-early-return (VISIBILITY skips the steps after an interior pick),
/// ace-neighbour-via-visible-cells (VISIBILITY lets a portal neighbour the walked cell does not see be ACE's hint), ace-load-hint-low-key
/// (PORTAL-TRANSIT, SCENE-SOUNDNESS and SCENE-TRANSLATION read a hint under its 16-bit key) and ace-no-portal-guard
/// (<see cref="SceneOracle.Pickable"/>, HYSTERESIS-INDOOR); those switches, and the ones that break nothing measured
/// (ace-filter-outside-guard, ace-outside-by-cell-id, drop-unloaded-land-cells, ace-transition-filter, ace-box-side-pairing,
/// reframe-transit, double), have no row.
/// </remarks>
public static class BrokenByDesign
{
    private static readonly System.Collections.Concurrent.ConcurrentDictionary<(IndoorFidelity Indoor, OutdoorFidelity Outdoor), IReadOnlyList<string>> Declared = new();

    private static readonly Row[] Table =
    [
        // §7 #6, §4 step 1: ACE does not clear the array, so the walk's earlier queries' cells stay candidates (out of the
        // body's reach, a hint the body no longer straddles the portal of, picked as the containing cell without a portal
        // between). The array lives for one walk (ReferenceAdapter.FindCellWalk), so VISIBILITY, SCENE-TRANSLATION and
        // NEVER-NULL, which failed while it lived for a whole run, are judged again (issue 41).
        new("ace-keeps-stale-cells", "§7 #6, §4 step 1: the array is not cleared between the queries of a walk", ["PORTAL-TRANSIT", "NO-TUNNEL", "SCENE-SOUNDNESS", "ENV-CANDIDATE-JUSTIFIED", "TIES-PINNED-INDOOR"]),
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
        // Asked for every invariant of every case a fuzz input or a replay judges: the names of a declaration are made once.
        var declared = Declared.GetOrAdd((indoor, outdoor), d => FidelityNames.Names(d.Indoor, d.Outdoor));
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
