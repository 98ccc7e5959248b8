namespace AcPhys.Formats.Values;

/// <summary>
/// The rule for a list of spheres wherever one is read (a walk's body, a protocol request's <c>spheres</c>): at most
/// <see cref="Max"/> of them; empty where the query then reads the position's own point (facts §3.3 step 3, issue 18).
/// </summary>
internal static class SphereList
{
    /// <summary>The most spheres one list may hold (bounded input).</summary>
    public const int Max = 10_000;

    /// <summary>Returns what is wrong with a list's length, or null when it is valid.</summary>
    /// <param name="count">The number of spheres.</param>
    /// <param name="min">The fewest allowed: 0 where an empty list reads the position's point, 1 where sphere 0 is judged (walk files).</param>
    /// <returns>The problem (no location), or null.</returns>
    public static string? Problem(int count, int min) =>
        count >= min && count <= Max ? null : string.Create(System.Globalization.CultureInfo.InvariantCulture, $"expected an array of {min} to {Max:N0} spheres, got {count:N0}");
}
