namespace AcPhys.Core;

/// <summary>The arithmetic of the outdoor cell math: retail float32, or a double-precision reference that is exact for float32 inputs.</summary>
public enum OutdoorPrecision
{
    /// <summary>Retail: re-base, 24 − r and the pick's re-expressed centre round to float32 (facts §2.1, §3.2, §4; docs/numerics.md).</summary>
    Float32 = 0,

    /// <summary>
    /// Reference: the same rules (EPS snap, floor, strict neighbour tests, closed squares, last wins) computed in
    /// double, where every step is exact for float32 inputs on the map (docs/numerics.md §7 gives the argument).
    /// </summary>
    Double = 1,
}
