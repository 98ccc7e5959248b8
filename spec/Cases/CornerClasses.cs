namespace AcPhys.Spec.Cases;

/// <summary>Case classes of issue 27's corner recipes (near-touch spheres, load hints ahead in the closure).</summary>
internal static class CornerClasses
{
    /// <summary>Returns the classes of a recipe.</summary>
    /// <param name="r">The recipe.</param>
    /// <returns>Tags (none for other recipes).</returns>
    public static IEnumerable<string> Of(SceneRecipe r)
    {
        if (r.NearTouch is { } n)
        {
            // facts §6.10: which padded test the gaps r, r ± EPS/2, r ± 0.005, r + 0.01 ± ulps straddle.
            yield return n.Target switch
            {
                NearTarget.Neighbour => "near:neighbour",
                NearTarget.Building => "near:building",
                NearTarget.ExitPlane => "near:exit-plane",
                _ => "near:hint-plane",
            };
        }

        if (r.HintHub is not null)
        {
            yield return "dungeon:hint-ahead"; // facts §4 step 4a: a load hint early in breadth-first order, loaded cells after it
        }
    }
}
