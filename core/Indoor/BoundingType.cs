namespace AcPhys.Core;

/// <summary>The answer of <c>sphere_intersects_cell</c> (BN:12-17; the seed's Outside / Crossing / Inside). Callers only test ≠ Outside.</summary>
public enum BoundingType
{
    /// <summary>The sphere misses the cell.</summary>
    Outside = 0,

    /// <summary>The sphere straddles a boundary plane (the seed's "Crossing").</summary>
    PartiallyInside = 1,

    /// <summary>The sphere lies inside every plane of the chain.</summary>
    EntirelyInside = 2,
}
