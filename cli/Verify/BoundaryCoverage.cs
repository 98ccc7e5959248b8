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

    /// <summary>Returns a short coverage text: hits of all tags, plus what was missed or the rarest boundary coordinates.</summary>
    /// <param name="classes">Hit counts by tag.</param>
    /// <returns>E.g. <c>23: rarest subnormal 41, eps-edge 57</c> or <c>20, missed cell:env, coord:huge</c>.</returns>
    public static string Brief(IReadOnlyDictionary<string, int> classes)
    {
        if (!classes.Keys.Any(AllTags.Contains))
        {
            // Outdoor queries and walks carry their own classes (PlaceClasses): report what was hit, rarest first.
            var rare = classes.OrderBy(k => k.Value).Take(3).Select(k => $"{k.Key} {Fmt.Count(k.Value)}");
            return $"{classes.Count} classes; rarest {string.Join(", ", rare)}";
        }

        var missed = Missed(classes);
        if (missed.Count > 0)
        {
            return $"{Hit(classes)}, missed {string.Join(", ", missed.Take(3))}{(missed.Count > 3 ? $" +{missed.Count - 3}" : string.Empty)}";
        }

        var rarest = BoundaryCoordinateTags.OrderBy(t => classes.GetValueOrDefault(t)).Take(3)
            .Select(t => $"{t["coord:".Length..]} {Fmt.Count(classes.GetValueOrDefault(t))}");
        return $"all {Hit(classes)}; rarest {string.Join(", ", rarest)}";
    }
}
