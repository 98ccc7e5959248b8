using AcPhys.Spec.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Issue 41's indoor corners: spheres exactly at a comparison's bound in the tested cell's frame
/// (<see cref="ExactBoundPlan"/>) and interiors side by side.
/// </summary>
public static class InteriorGens
{
    /// <summary>Gets exact-bound plans, placed inside one block (a wall 6–14 m into a land cell, so a building and the tie share it).</summary>
    public static Gen<ExactBoundPlan> ExactBounds { get; } =
        from target in Gen.Elements(NearTarget.Neighbour, NearTarget.Building, NearTarget.ExitPlane, NearTarget.HintPlane)
        from xb in Gen.Choose(1, 0xFD)
        from yb in Gen.Choose(1, 0xFD)
        from cx in Gen.Choose(0, 5)
        from cy in Gen.Choose(0, 6)
        from inX in Gen.Choose(6 * 1024, 14 * 1024)
        from inY in Gen.Choose(4 * 1024, 16 * 1024)
        from length in Gen.Choose(16, 40).Select(i => i / 4f)
        from mesh in Gen.Choose(410, 1024)
        from offsets in Gen.Choose(0, 0xFFFF)
        from turns in Gen.Choose(0, 3)
        from flips in Gen.Choose(0, 3)
        from start in Gen.Choose(0, 3)
        select new ExactBoundPlan(target, (192.0 * xb) + (24 * cx) + (inX / 1024.0), (192.0 * yb) + (24 * cy) + (inY / 1024.0), length, mesh, offsets, turns, flips, start);

    /// <summary>Gets the recipes of both corners.</summary>
    public static Gen<SceneRecipe> Recipes { get; } = Gen.Frequency(
        (1, from plan in ExactBounds
            select new SceneRecipe(null, null, SceneRoute.ExactBound, 0, plan.Radius, false, plan.Radius, SceneGens.Jitters[0], int.MaxValue) { Plan = plan }));
}
