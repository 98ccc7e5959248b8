using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Shrinks a scene walk through its recipe toward a small scene a person reads at a glance: fewer steps, fewer rooms,
/// no storey or back door, no yaw, no flipped portals, loaded neighbours, one sphere of radius 0.5, longer steps.
/// A stored case (no recipe) shrinks by dropping trailing steps.
/// </summary>
public static class SceneShrinker
{
    /// <summary>Returns simpler candidates, most aggressive first.</summary>
    /// <param name="w">The failing case.</param>
    /// <returns>Candidates.</returns>
    public static IEnumerable<SceneWalk> Shrink(SceneWalk w)
    {
        if (w.Recipe is not SceneRecipe recipe)
        {
            for (int n = w.Walk.Steps.Count / 2; n < w.Walk.Steps.Count; n = n == 0 ? 1 : n + Math.Max(1, (w.Walk.Steps.Count - n) / 2))
            {
                yield return w with { Walk = w.Walk with { Steps = [.. w.Walk.Steps.Take(n)] } };
            }

            yield break;
        }

        int steps = w.Walk.Steps.Count;
        foreach (var r in Recipes(recipe, steps).Distinct().Where(r => r != recipe))
        {
            yield return r.Build();
        }
    }

    private static IEnumerable<SceneRecipe> Recipes(SceneRecipe r, int steps)
    {
        if (steps > 0)
        {
            yield return r with { Take = steps / 2 };
            yield return r with { Take = steps - 1 };
        }

        foreach (var corner in CornerShrinker.Recipes(r))
        {
            yield return corner;
        }

        foreach (var plan in r.Plan?.Shrink() ?? [])
        {
            yield return r with { Plan = plan };
        }

        if (r.Estate is not null)
        {
            foreach (var e in EstateShrinker.Recipes(r))
            {
                yield return e;
            }
        }

        if (r.Cottage is { } c)
        {
            if (c.Rooms > 1)
            {
                yield return r with { Cottage = c with { Rooms = c.Rooms - 1 }, Target = Math.Min(r.Target, c.Rooms - 2) };
            }

            if (c.Storey && r.Route != SceneRoute.Storey)
            {
                yield return r with { Cottage = c with { Storey = false } };
            }

            if (c.BackDoor && r.Route != SceneRoute.Through)
            {
                yield return r with { Cottage = c with { BackDoor = false } };
            }

            if (c.Yaw != 0)
            {
                yield return r with { Cottage = c with { Yaw = 0 } };
            }

            if (c.Flips != 0)
            {
                yield return r with { Cottage = c with { Flips = 0 } };
            }

            if (!c.LoadNeighbours)
            {
                yield return r with { Cottage = c with { LoadNeighbours = true } };
            }

            if (c.Width != 6 || c.Depth != 6)
            {
                yield return r with { Cottage = c with { Width = 6, Depth = 6 } };
            }

            if (r.Route is SceneRoute.EnterAndBack or SceneRoute.Through)
            {
                yield return r with { Route = SceneRoute.Enter, Take = int.MaxValue };
            }
        }

        if (r.Dungeon is { } d)
        {
            if (d.Cells > 2 && d.Cells - 1 > d.Unloaded)
            {
                yield return r with { Dungeon = d with { Cells = d.Cells - 1 } };
            }

            if (d.Unloaded > 0)
            {
                yield return r with { Dungeon = d with { Unloaded = d.Unloaded - 1 } };
            }

            if (d.Flips != 0)
            {
                yield return r with { Dungeon = d with { Flips = 0 } };
            }

            if (r.Route == SceneRoute.DungeonRunAndBack)
            {
                yield return r with { Route = SceneRoute.DungeonRun, Take = int.MaxValue };
            }
        }

        if (r.TwoSpheres && r.Estate is null)
        {
            yield return r with { TwoSpheres = false };
        }

        if (r.Radius != 0.5f)
        {
            yield return r with { Radius = 0.5f, StepMax = Math.Min(r.StepMax, 0.5f) };
        }

        if (r.StepMax < r.Radius)
        {
            yield return r with { StepMax = r.Radius };
        }
    }
}
