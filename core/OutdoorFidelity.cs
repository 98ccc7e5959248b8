namespace AcPhys.Core;

/// <summary>Which behaviour to follow where ACE and retail differ on the outdoor paths (facts §7). Retail by default.</summary>
/// <param name="DropUnloadedCells">ACE (§7 #2): skip a land cell whose block is not loaded; retail adds it as a load hint.</param>
public readonly record struct OutdoorFidelity(bool DropUnloadedCells = false)
{
    /// <summary>Gets retail behaviour.</summary>
    public static OutdoorFidelity Retail => default;

    /// <summary>Gets ACE's behaviour, as documented divergences.</summary>
    public static OutdoorFidelity Ace => new(DropUnloadedCells: true);
}
