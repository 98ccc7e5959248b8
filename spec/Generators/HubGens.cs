using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Hub generators (<see cref="HubPlan"/>): four small quadrants meeting at a corner, some inner walls sealed, exits on
/// some outer walls, shuffled portal orders, VisibleCells missing some cells (portal neighbours too); the corner often
/// within a metre and a half of a 24 m line, so a straddled exit adds two or four land cells. The walk turns inside Q0
/// at a fraction of the radius from both inner walls: the body reaches all four quadrants (and, with a low storey,
/// the quadrants above).
/// </summary>
internal static class HubGens
{
    /// <summary>Gets hub plans.</summary>
    public static Gen<HubPlan> Plans { get; } =
        from size in Gen.Choose(24, 80).Two().Select(t => (t.Item1 / 32f, t.Item2 / 32f))
        from sealedWalls in Gen.Frequency((3, Gen.Constant(0)), (1, Gen.Choose(1, 15)))
        from exits in Gen.Choose(0, 255).Select(e => e | 1)
        from blind in Gen.Frequency((1, Gen.Constant(0)), (3, Gen.Choose(0, 0xFFFF)))
        from order in Gen.Choose(0, 0xFFFFFF)
        from flips in Gen.Choose(0, 0xFFFF)
        from block in Gen.Choose(2, 0xFC).Two()
        from near in Gen.Choose(0, 1).Two()
        from along in Gen.Choose(1, 7).Two()
        from off in Gen.Choose(-48, 48).Two()
        from free in Gen.Choose(24 * 32, 168 * 32).Two()
        select new HubPlan(
            Place(block.Item1, near.Item1, along.Item1, off.Item1, free.Item1),
            Place(block.Item2, near.Item2, along.Item2, off.Item2, free.Item2),
            size.Item1,
            size.Item2,
            sealedWalls,
            exits,
            blind,
            order,
            flips);

    /// <summary>Gets hub recipes: a plan, a one- or two-sphere body, the turning point at 1/8 to 5/8 of the radius from the inner walls.</summary>
    public static Gen<SceneRecipe> Recipes { get; } =
        from plan in Plans
        from r in Gen.Choose(12, 32).Select(i => i / 32f)
        from two in Gen.Elements(true, false)
        from eighths in Gen.Choose(1, 5)
        from stepFraction in Gen.Elements(0.25f, 0.5f, 1f)
        from storey in Gen.Frequency((1, Gen.Constant(false)), (1, Gen.Constant(true)))
        from height in Gen.Choose(56, 72).Select(i => i / 32f)
        from blindUp in Gen.Frequency((1, Gen.Constant(0)), (2, Gen.Choose(0, 0xFFFF)))
        select new SceneRecipe(null, null, SceneRoute.Hub, 0, r, two || storey, r * stepFraction, SceneGens.Jitters[0], int.MaxValue)
        {
            // A storey's ceiling at 1.75–2.25 m: the upper sphere (1.3 m up) of a body of radius ≥ 0.5 reaches it.
            Hub = plan with { Inset = r * eighths / 8, Storey = storey, Height = storey ? height : 3f, BlindUp = blindUp },
        };

    // A world coordinate: near a 24 m line (within ±1.5 m) or anywhere in the block's inner part (1/32 m grid).
    private static double Place(int block, int near, int along, int off, int free) =>
        (192.0 * block) + (near == 1 ? (24.0 * along) + (off / 32.0) : free / 32.0);
}
