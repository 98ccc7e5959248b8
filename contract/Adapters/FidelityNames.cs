using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>
/// Protocol names of the documented deviations an implementation may declare in <c>hello</c> (<c>"fidelity"</c>, docs/protocol.md):
/// one name per switch of <see cref="IndoorFidelity"/> and <see cref="OutdoorFidelity"/> (facts §7), plus <c>ace</c> for
/// every ACE difference at once and <c>double</c> for the double-precision outdoor arithmetic.
/// </summary>
public static class FidelityNames
{
    private static readonly (string Name, Func<IndoorFidelity, bool> Get, Func<IndoorFidelity, IndoorFidelity> Set)[] Indoor =
    [
        ("ace-keeps-stale-cells", f => f.AceKeepsStaleCells, f => f with { AceKeepsStaleCells = true }),
        ("ace-early-return", f => f.AceEarlyReturn, f => f with { AceEarlyReturn = true }),
        ("ace-filter-outside-guard", f => f.AceFilterOutsideGuard, f => f with { AceFilterOutsideGuard = true }),
        ("ace-neighbour-via-visible-cells", f => f.AceNeighbourViaVisibleCells, f => f with { AceNeighbourViaVisibleCells = true }),
        ("ace-load-hint-low-key", f => f.AceLoadHintLowKey, f => f with { AceLoadHintLowKey = true }),
        ("ace-outside-by-cell-id", f => f.AceOutsideByCellId, f => f with { AceOutsideByCellId = true }),
        ("ace-no-portal-guard", f => f.AceNoPortalGuard, f => f with { AceNoPortalGuard = true }),
        ("drop-unloaded-land-cells", f => f.DropUnloadedLandCells, f => f with { DropUnloadedLandCells = true }),
        ("reframe-transit", f => f.ReframeTransit, f => f with { ReframeTransit = true }),
        ("ace-transition-filter", f => f.AceTransitionFilters, f => f with { AceTransitionFilters = true }),
        ("ace-box-side-pairing", f => f.AceBoxSidePairing, f => f with { AceBoxSidePairing = true }),
    ];

    /// <summary>The name of every ACE difference at once.</summary>
    public const string Ace = "ace";

    /// <summary>The name of the double-precision outdoor arithmetic.</summary>
    public const string Double = "double";

    /// <summary>Gets every name this version knows.</summary>
    public static IReadOnlyList<string> Known { get; } = [Ace, Double, .. Indoor.Select(t => t.Name)];

    /// <summary>Returns the names of a declared mode (empty for retail).</summary>
    /// <param name="indoor">Indoor deviations.</param>
    /// <param name="outdoor">Outdoor deviations.</param>
    /// <returns>The names.</returns>
    public static IReadOnlyList<string> Names(IndoorFidelity indoor, OutdoorFidelity outdoor)
    {
        var names = Indoor.Where(t => t.Get(indoor)).Select(t => t.Name).ToList();
        if (outdoor.Precision == OutdoorPrecision.Double)
        {
            names.Add(Double);
        }

        return names;
    }

    /// <summary>Parses declared names.</summary>
    /// <param name="names">The names.</param>
    /// <param name="indoor">The indoor deviations.</param>
    /// <param name="outdoor">The outdoor deviations (the ACE drop of unloaded land cells follows the indoor switch).</param>
    /// <param name="unknown">The first unknown name, or null.</param>
    /// <returns>True when every name is known.</returns>
    public static bool TryParse(IEnumerable<string> names, out IndoorFidelity indoor, out OutdoorFidelity outdoor, out string? unknown)
    {
        indoor = IndoorFidelity.Retail;
        bool isDouble = false;
        unknown = null;
        foreach (var name in names)
        {
            if (name == Ace)
            {
                indoor = IndoorFidelity.Ace with { ReframeTransit = indoor.ReframeTransit };
            }
            else if (name == Double)
            {
                isDouble = true;
            }
            else if (Array.FindIndex(Indoor, t => t.Name == name) is int i and >= 0)
            {
                indoor = Indoor[i].Set(indoor);
            }
            else
            {
                unknown = name;
                outdoor = default;
                return false;
            }
        }

        outdoor = new OutdoorFidelity(indoor.DropUnloadedLandCells, isDouble ? OutdoorPrecision.Double : OutdoorPrecision.Float32);
        return true;
    }
}
