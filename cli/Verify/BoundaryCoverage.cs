using AcPhys.Spec.Cases;

namespace AcPhys.Cli.Verify;

/// <summary>Summarises which boundary classes (coordinate, cell id, lcoord) a run's generated cases hit.</summary>
internal static class BoundaryCoverage
{
    /// <summary>Gets every class tag a case can carry, most boundary-like first within each group.</summary>
    public static IReadOnlyList<string> AllTags { get; } =
        [.. BoundaryClasses.CoordinateClasses.Select(c => "coord:" + c), .. BoundaryClasses.CellClasses, .. BoundaryClasses.LcoordClasses];

    /// <summary>Gets the coordinate classes that are real boundaries (everything but negative, far and interior).</summary>
    public static IReadOnlyList<string> BoundaryCoordinateTags { get; } =
        BoundaryClasses.CoordinateClasses.Where(c => c is not ("negative" or "far" or "interior")).Select(c => "coord:" + c).ToArray();

    /// <summary>Returns the known tags that were not hit.</summary>
    /// <param name="classes">Hit counts by tag.</param>
    /// <returns>The missed tags in catalogue order.</returns>
    public static IReadOnlyList<string> Missed(IReadOnlyDictionary<string, int> classes) =>
        AllTags.Where(t => classes.GetValueOrDefault(t) == 0).ToArray();

    /// <summary>Returns how many of the known tags were hit.</summary>
    /// <param name="classes">Hit counts by tag.</param>
    /// <returns>The count.</returns>
    public static int Hit(IReadOnlyDictionary<string, int> classes) => AllTags.Count(t => classes.GetValueOrDefault(t) > 0);
}
