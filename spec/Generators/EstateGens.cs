using System.Numerics;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Estate generators: room graphs that branch or loop (some shared walls sealed), 1–4 doors (some invalid), per-cell frames with tilt, storeys and
/// stairwells, L-shaped rooms, vestibules, unloaded rooms, neighbouring buildings, lead-in dungeons; walks through the
/// rooms or outdoors along a facade; placed anywhere,
/// across a block line or at a four-block corner; bodies of 1–3 spheres of different radii.
/// </summary>
internal static class EstateGens
{
    /// <summary>Gets estate plans.</summary>
    public static Gen<EstatePlan> Plans { get; } =
        from layout in Gen.Elements(EstateLayout.Row, EstateLayout.Branch, EstateLayout.Ring)
        from rooms in Gen.Frequency((1, Gen.Choose(1, 3)), (3, Gen.Choose(4, 6)))
        from size in Gen.Choose(16, 32).Two().Select(t => (t.Item1 / 4f, t.Item2 / 4f))
        from doors in Gen.Choose(1, 4)
        from invalid in Gen.Frequency((2, Gen.Constant(0)), (1, Gen.Choose(1, 15)))
        from yaw in Gen.Frequency((1, Gen.Constant(0f)), (3, Gen.Choose(0, 1023).Select(i => i * 2 * MathF.PI / 1024)))
        from tilt in Gen.Frequency((2, Gen.Constant(Vector2.Zero)), (1, Gen.Choose(-16, 16).Two().Select(t => new Vector2(t.Item1, t.Item2) / 1024f)))
        from turns in Gen.Choose(0, 0xFFF)
        from own in Gen.Frequency((1, Gen.Constant(false)), (3, Gen.Constant(true)))
        from flips in Gen.Choose(0, 0xFFFF)
        from extras in Gen.Frequency((5, Gen.Constant(0)), (2, Gen.Choose(1, 3)))
        from features in Gen.Choose(0, 0xFFFF)
        from sealedWalls in Gen.Frequency((2, Gen.Constant(0)), (1, Gen.Choose(1, 0x7F)))
        from doorsPick in Gen.Choose(0, 15).Two()
        from see in Gen.Elements(0, 1, 2, 2)
        from place in Places
        select new EstatePlan(place.X, place.Y, layout, rooms, size.Item1, size.Item2, doors, invalid, yaw, tilt, turns, own, flips)
        {
            Storey = (features & 3) == 0,
            Stairwell = (features & 7) == 0,
            LShapes = (features >> 3) % 3 == 0 ? (features >> 5) & 0x3F : 0,
            Vestibule = (features >> 11) % 4 == 0,
            UnloadedRoom = layout == EstateLayout.Ring && rooms >= 4 && (features >> 13) % 4 == 0 ? 3 : -1,
            SealedWalls = sealedWalls,
            SeeDepth = see,
            ExtraBuildings = extras,
            EntryDoor = doorsPick.Item1,
            ExitDoor = doorsPick.Item2,
        };

    /// <summary>Gets estate recipes: a plan, a route, a body of 1–3 spheres, steps mostly within sphere 0's radius.</summary>
    public static Gen<SceneRecipe> Recipes { get; } =
        from plan in Plans
        from route in Gen.Frequency(
            (4, Gen.Constant(SceneRoute.Through)), (3, Gen.Constant(SceneRoute.EnterAndBack)), (1, Gen.Constant(SceneRoute.Storey)),
            (1, Gen.Constant(SceneRoute.Stairwell)), (2, Gen.Constant(SceneRoute.LeadIn)), (3, Gen.Constant(SceneRoute.Facade)))
        from target in Gen.Choose(0, 5)
        from r0 in Gen.Choose(12, 32).Select(i => i / 32f)
        from spheres in Gen.Choose(1, 3)
        from r1 in Gen.Choose(8, 32).Select(i => i / 32f)
        from r2 in Gen.Choose(8, 19).Select(i => i / 32f)
        from stepFraction in Gen.Elements(0.25f, 0.5f, 1f)
        select new SceneRecipe(null, null, route, target, r0, false, r0 * stepFraction, SceneGens.Jitters[0], int.MaxValue)
        {
            Estate = Fit(plan, route),
            Spheres = spheres,
            Radius1 = r1,
            Radius2 = r2,
        };

    // The plan made fit for its route: a storey walk needs a storey, a stairwell walk a stairwell, a lead-in an
    // upright, unyawed building whose block has a block to the west (door 0 then opens west toward the lead-in); a
    // facade walk no vestibule (it would stand in the walk's way, a cell entered through its wall), and half the time a
    // terrace (every shared wall sealed: two doors' rooms meet at a wall with no portal) and half the time L rooms
    // (a door room's notch on the walked side).
    private static EstatePlan Fit(EstatePlan p, SceneRoute route) => route switch
    {
        SceneRoute.Storey => p with { Storey = true },
        SceneRoute.Stairwell => p with { Storey = true, Stairwell = true },
        SceneRoute.Facade => p with
        {
            Vestibule = false,
            SealedWalls = ((p.Flips >> 3) & 1) != 0 ? 0x7F : p.SealedWalls,
            LShapes = ((p.Flips >> 4) & 1) != 0 ? 0x3F : p.LShapes,
        },
        SceneRoute.LeadIn => p with { Lead = 1 + (p.Flips % 3), Yaw = 0, Tilt = Vector2.Zero, EntryDoor = 0, WorldX = (192.0 * Math.Floor(p.WorldX / 192)) + 8 + (p.Flips % 23) },
        _ => p,
    };

    // World origins: anywhere in a block; a few metres short of a block line (the building straddles it); at a four-block corner.
    private static Gen<(double X, double Y)> Places => Gen.Frequency(
        (2, from xb in Gen.Choose(3, 0xFA)
            from yb in Gen.Choose(3, 0xFA)
            from x in Gen.Choose(40, 150)
            from y in Gen.Choose(40, 150)
            select ((192.0 * xb) + x, (192.0 * yb) + y)),
        (2, from xb in Gen.Choose(3, 0xFA)
            from yb in Gen.Choose(3, 0xFA)
            from back in Gen.Choose(1, 24)
            from along in Gen.Choose(40, 150)
            from vertical in Gen.Elements(true, false)
            select vertical ? ((192.0 * xb) + along, (192.0 * yb) - back) : ((192.0 * xb) - back, (192.0 * yb) + along)),
        (1, from xb in Gen.Choose(3, 0xFA)
            from yb in Gen.Choose(3, 0xFA)
            from dx in Gen.Choose(-24, 8)
            from dy in Gen.Choose(-24, 8)
            select ((192.0 * xb) + dx, (192.0 * yb) + dy)));
}
