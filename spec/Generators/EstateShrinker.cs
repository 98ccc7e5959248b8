using System.Numerics;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Shrink candidates for estate recipes, most aggressive first: fewer buildings, no lead-in, fewer rooms and doors,
/// no storey, stairwell, vestibule, notches, sealed walls or unloaded room; shared frames (one frame per building, no tilt, yaw 0);
/// a row; plain portal encodings; fewer and equal spheres.
/// </summary>
internal static class EstateShrinker
{
    /// <summary>Returns simpler estate recipes.</summary>
    /// <param name="r">A recipe with an estate.</param>
    /// <returns>Candidates.</returns>
    public static IEnumerable<SceneRecipe> Recipes(SceneRecipe r)
    {
        var e = r.Estate!;
        SceneRecipe With(EstatePlan p) => r with { Estate = p };
        if (e.ExtraBuildings > 0)
        {
            yield return With(e with { ExtraBuildings = 0 });
            yield return With(e with { ExtraBuildings = e.ExtraBuildings - 1 });
        }

        if (e.Lead > 0 && r.Route != SceneRoute.LeadIn)
        {
            yield return With(e with { Lead = 0 });
        }

        if (e.Rooms > 1)
        {
            yield return With(e with { Rooms = 1, UnloadedRoom = -1 });
            yield return With(e with { Rooms = e.Rooms - 1, UnloadedRoom = e.UnloadedRoom < e.Rooms - 1 ? e.UnloadedRoom : -1 });
        }

        if (e.Doors > 1)
        {
            yield return With(e with { Doors = 1, EntryDoor = 0, ExitDoor = 0 });
            yield return With(e with { Doors = e.Doors - 1 });
        }

        if (e.OwnFrames || e.Tilt != Vector2.Zero || e.Yaw != 0)
        {
            yield return With(e with { OwnFrames = false, Tilt = Vector2.Zero, Yaw = 0 });
        }

        if (e.OwnFrames)
        {
            yield return With(e with { OwnFrames = false });
        }

        if (e.Tilt != Vector2.Zero)
        {
            yield return With(e with { Tilt = Vector2.Zero });
        }

        if (e.Yaw != 0)
        {
            yield return With(e with { Yaw = 0 });
        }

        if (e.Stairwell && r.Route != SceneRoute.Stairwell)
        {
            yield return With(e with { Stairwell = false });
        }

        if (e.Storey && r.Route is not (SceneRoute.Storey or SceneRoute.Stairwell))
        {
            yield return With(e with { Storey = false, Stairwell = false });
        }

        if (e.Vestibule)
        {
            yield return With(e with { Vestibule = false });
        }

        if (e.LShapes != 0)
        {
            yield return With(e with { LShapes = 0 });
        }

        if (e.SealedWalls != 0)
        {
            yield return With(e with { SealedWalls = 0 });
        }

        if (e.UnloadedRoom >= 0)
        {
            yield return With(e with { UnloadedRoom = -1 });
        }

        if (e.InvalidDoors != 0)
        {
            yield return With(e with { InvalidDoors = 0 });
        }

        if (e.Layout != EstateLayout.Row)
        {
            yield return With(e with { Layout = EstateLayout.Row, UnloadedRoom = -1 });
        }

        if (e.Flips != 0 && r.Route != SceneRoute.LeadIn)
        {
            yield return With(e with { Flips = 0 });
        }

        if (e.CellTurns != 0)
        {
            yield return With(e with { CellTurns = 0 });
        }

        if (e.SeeDepth != 0)
        {
            yield return With(e with { SeeDepth = 0 });
        }

        if (r.Route is SceneRoute.EnterAndBack or SceneRoute.Through or SceneRoute.Stairwell or SceneRoute.Storey)
        {
            yield return r with { Route = SceneRoute.Enter, Take = int.MaxValue };
        }

        if (r.Spheres > 1)
        {
            yield return r with { Spheres = 1 };
            yield return r with { Spheres = r.Spheres - 1 };
        }

        if (r.Spheres > 1 && (r.Radius1 != r.Radius || (r.Spheres > 2 && r.Radius2 != r.Radius)))
        {
            yield return r with { Radius1 = r.Radius, Radius2 = Math.Min(r.Radius, 0.59375f) };
        }
    }
}
