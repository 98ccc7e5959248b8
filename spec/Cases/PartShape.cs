namespace AcPhys.Spec.Cases;

/// <summary>The kind of a generated part's box (<see cref="PartShapes"/>).</summary>
internal enum PartShape
{
    /// <summary>Well inside the part's sphere: every corner within 0.48·r of the origin.</summary>
    Tidy,

    /// <summary>Poking out of the sphere: corners from 0.86·r to 1.65·r, the box within [−r, r]³.</summary>
    Poking,

    /// <summary>A flat plate 0.07·r thick.</summary>
    Flat,

    /// <summary>A long stick 1.9·r long.</summary>
    Long,
}
