namespace AcPhys.Core;

/// <summary>Retail or ACE behaviour for the parts / bounding-box variant (facts §3.4, §7 #3–#4). Retail by default.</summary>
/// <param name="SameBlockGuard">ACE (§7 #3): add_cell_block skips cells outside the calling cell's landblock (its "FIXME" guard).</param>
/// <param name="EveryPartAnchors">ACE (§7 #4): every part is an anchor with its own add_cell_block call, over a range that only grows.</param>
public readonly record struct PartsFidelity(bool SameBlockGuard = false, bool EveryPartAnchors = false)
{
    /// <summary>Gets retail behaviour.</summary>
    public static PartsFidelity Retail => default;

    /// <summary>Gets ACE's behaviour.</summary>
    public static PartsFidelity Ace => new(SameBlockGuard: true, EveryPartAnchors: true);
}
