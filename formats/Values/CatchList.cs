using System.Globalization;

namespace AcPhys.Formats.Values;

/// <summary>
/// The rule for a corpus entry's <c>catches</c> (the planted faults its case catches) wherever one is read: at most
/// <see cref="Max"/> names, as many as there could be faults and more; two million once took 3.5 GB (issue 28).
/// </summary>
internal static class CatchList
{
    /// <summary>The most fault names one entry may list.</summary>
    public const int Max = 256;

    /// <summary>Returns what is wrong with a list's length, or null when it is valid.</summary>
    /// <param name="count">The number of names.</param>
    /// <returns>The problem (no location), or null.</returns>
    public static string? Problem(int count) =>
        count <= Max ? null : string.Create(CultureInfo.InvariantCulture, $"expected at most {Max} fault ids, got {count:N0}");
}
