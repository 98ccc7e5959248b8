using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Shrinks issue 27's corner recipes toward the smallest scene that still shows the corner: the near-touch geometry
/// (target, threshold mesh, gaps) and the hint-ahead layout are kept; cells, flips, sizes and the start go.
/// </summary>
internal static class CornerShrinker
{
    /// <summary>Returns simpler recipes.</summary>
    /// <param name="r">The recipe.</param>
    /// <returns>Candidates.</returns>
    public static IEnumerable<SceneRecipe> Recipes(SceneRecipe r)
    {
        if (r.NearTouch is { } n)
        {
            int fewest = n.Target == NearTarget.Building ? 1 : 2;
            if (n.Cells > fewest)
            {
                yield return r with { NearTouch = n with { Cells = n.Cells - 1 } };
            }

            if (n.Flips != 0)
            {
                yield return r with { NearTouch = n with { Flips = 0 } };
            }

            if (n.StartAt != 0)
            {
                yield return r with { NearTouch = n with { StartAt = 0 } };
            }

            if (n.Length != 6)
            {
                yield return r with { NearTouch = n with { Length = 6 } };
            }
        }

        if (r.HintHub is { } h)
        {
            if (h.Flips != 0)
            {
                yield return r with { HintHub = h with { Flips = 0 } };
            }

            if (h.Mirror)
            {
                yield return r with { HintHub = h with { Mirror = false } };
            }

            if (h.Size != 6)
            {
                yield return r with { HintHub = h with { Size = 6 } };
            }
        }
    }
}
