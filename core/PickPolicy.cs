namespace AcPhys.Core;

/// <summary>How the containing cell is chosen among the candidates (facts §4 step 4b).</summary>
public enum PickPolicy
{
    /// <summary>Retail: closed squares, the last outdoor cell containing sphere 0's centre wins; the pick depends on the position alone.</summary>
    Retail,

    /// <summary>acdream's hysteresis: the current cell is kept while it still contains the centre; otherwise the retail rule.</summary>
    CurrentFirst,
}
