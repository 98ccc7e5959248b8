namespace AcPhys.Core;

/// <summary>Which behaviour to follow where ACE and retail differ on the outdoor paths (facts §7), and in which arithmetic. Retail by default.</summary>
/// <param name="DropUnloadedCells">ACE (§7 #2): skip a land cell whose block is not loaded; retail adds it as a load hint.</param>
/// <param name="Precision">Retail float32, or the exact double-precision reference (docs/tradeoffs.md measures the difference).</param>
public readonly record struct OutdoorFidelity(bool DropUnloadedCells = false, OutdoorPrecision Precision = OutdoorPrecision.Float32)
{
    /// <summary>Gets retail behaviour.</summary>
    public static OutdoorFidelity Retail => default;

    /// <summary>Gets ACE's behaviour, as documented divergences.</summary>
    public static OutdoorFidelity Ace => new(DropUnloadedCells: true);

    /// <summary>Gets retail rules in the exact double-precision arithmetic.</summary>
    public static OutdoorFidelity Double => new(Precision: OutdoorPrecision.Double);
}
