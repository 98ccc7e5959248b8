using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Scene-walk generators: cottages of 1–4 rooms (doors outside and between rooms, both PortalSide encodings, any yaw,
/// anywhere: across block lines, at the map edge, next to unloaded blocks, with a storey), and dungeon chains crossing
/// into the next block with unloaded tails; routes in, through, out and back, jitter at portals and land lines.
/// </summary>
public static class SceneGens
{
    /// <summary>Jitter amplitudes: powers of two, so a jitter walk returns exactly to its line.</summary>
    public static readonly float[] Jitters = [1f / 1024, 1f / 64, 1f / 8];

    /// <summary>Gets cottages placed anywhere, across a block line, or at the map edge.</summary>
    public static Gen<CottagePlan> Cottages { get; } =
        from rooms in Gen.Choose(1, 4)
        from width in Gen.Choose(16, 32).Select(i => i / 4f)
        from depth in Gen.Choose(16, 32).Select(i => i / 4f)
        from yaw in Gen.Frequency((2, Gen.Constant(0f)), (1, Gen.Choose(0, 3).Select(k => k * MathF.PI / 2)), (3, Gen.Choose(0, 1023).Select(i => i * 2 * MathF.PI / 1024)))
        from flips in Gen.Choose(0, 255)
        from backDoor in Gen.Elements(true, false)
        from storey in Gen.Frequency((4, Gen.Constant(false)), (1, Gen.Constant(true)))
        from neighbours in Gen.Frequency((4, Gen.Constant(true)), (1, Gen.Constant(false)))
        from place in Places(rooms * width)
        select new CottagePlan(place.X, place.Y, yaw, rooms, width, depth, flips, backDoor, storey, neighbours);

    /// <summary>Gets dungeon chains, mostly crossing into the next block.</summary>
    public static Gen<DungeonPlan> Dungeons { get; } =
        from cells in Gen.Choose(2, 5)
        from length in Gen.Choose(16, 40).Select(i => i / 4f)
        from unloaded in Gen.Choose(0, Math.Min(2, cells - 1))
        from flips in Gen.Choose(0, 255)
        from place in Places(cells * length)
        select new DungeonPlan(place.X, place.Y, cells, length, unloaded, flips);

    /// <summary>Gets recipes.</summary>
    public static Gen<SceneRecipe> Recipes { get; } = Gen.Frequency(
        (5, from c in Cottages
            from route in Gen.Frequency(
                (3, Gen.Constant(SceneRoute.Enter)), (3, Gen.Constant(SceneRoute.EnterAndBack)), (2, Gen.Constant(SceneRoute.Through)),
                (2, Gen.Constant(SceneRoute.PortalJitter)), (2, Gen.Constant(SceneRoute.LineJitter)), (1, Gen.Constant(SceneRoute.Storey)),
                (1, Gen.Constant(SceneRoute.Closet)))
            from target in Gen.Choose(0, c.Rooms - 1)
            from body in Bodies
            select new SceneRecipe(
                c with { BackDoor = c.BackDoor || route == SceneRoute.Through, Storey = c.Storey || route == SceneRoute.Storey, Closet = route == SceneRoute.Closet },
                null, route, target, body.Radius, body.Two, body.Step, body.Jitter, int.MaxValue)),
        (2, from d in Dungeons
            from back in Gen.Elements(SceneRoute.DungeonRun, SceneRoute.DungeonRunAndBack)
            from body in Bodies
            select new SceneRecipe(null, d, back, 0, body.Radius, body.Two, body.Step, body.Jitter, int.MaxValue)),
        (7, EstateGens.Recipes),
        (1, HubGens.Recipes),
        (1, CornerGens.Recipes),
        (1, InteriorGens.Recipes));

    /// <summary>Gets the arbitrary for scene walks, with the recipe shrinker.</summary>
    public static Arbitrary<SceneWalk> Arbitrary { get; } = Arb.From(Recipes.Select(r => r.Build()), SceneShrinker.Shrink);

    private static Gen<(float Radius, bool Two, float Step, float Jitter)> Bodies =>
        from r in Gen.Choose(12, 32).Select(i => i / 32f)
        from two in Gen.Elements(true, false)
        from stepFraction in Gen.Elements(0.25f, 0.5f, 1f)
        from jitter in Gen.Elements(Jitters)
        select (r, two, r * stepFraction, jitter);

    // World origins (metres): anywhere; within `extent` west/south of a block line so the building straddles it; at the map edge.
    private static Gen<(double X, double Y)> Places(float extent) => Gen.Frequency(
        (3, from xb in Gen.Choose(1, 0xFD)
            from yb in Gen.Choose(1, 0xFD)
            from x in Gen.Choose(16, 160)
            from y in Gen.Choose(16, 160)
            select ((192.0 * xb) + x, (192.0 * yb) + y)),
        (4, from xb in Gen.Choose(1, 0xFD)
            from yb in Gen.Choose(1, 0xFD)
            from back in Gen.Choose(1, Math.Max(2, (int)extent))
            from along in Gen.Choose(16, 160)
            from vertical in Gen.Elements(true, false)
            select vertical ? ((192.0 * xb) + along, (192.0 * (yb + 1)) - back) : ((192.0 * (xb + 1)) - back, (192.0 * yb) + along)),
        (1, from high in Gen.Elements(true, false)
            from yb in Gen.Choose(1, 0xFD)
            from x in Gen.Choose(3, 12)
            from y in Gen.Choose(16, 160)
            select (high ? (192.0 * 0xFF) - x - extent : x, (192.0 * yb) + y)));
}
