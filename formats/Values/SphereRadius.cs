namespace AcPhys.Formats.Values;

/// <summary>
/// The rule for a sphere's radius wherever one is read (corpus walks and parts, protocol requests, dat records): a
/// finite number ≥ 0. A negative or non-finite radius describes no body; retail never builds one.
/// </summary>
public static class SphereRadius
{
    /// <summary>Returns what is wrong with a radius, or null when it is valid.</summary>
    /// <param name="r">The radius.</param>
    /// <returns>The problem (no location), or null.</returns>
    public static string? Problem(float r) => !float.IsFinite(r) ? "radius must be finite" : r < 0 ? "radius must be ≥ 0" : null;
}
