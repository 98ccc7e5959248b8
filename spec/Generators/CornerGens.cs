using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Issue 27's two indoor corners: near-touch spheres (facts §6.10: +EPS for portal planes, +0.01 inside the BSP sphere
/// test, none for the neighbour and building callers) and load hints early in the transit closure (facts §4 step 4a).
/// </summary>
internal static class CornerGens
{
    /// <summary>Gets near-touch plans: a neighbour's volume, a building's room, an exit plane or a load-hint plane.</summary>
    public static Gen<NearTouchPlan> NearTouches { get; } =
        from target in Gen.Elements(NearTarget.Neighbour, NearTarget.Building, NearTarget.ExitPlane, NearTarget.HintPlane)
        from xb in Gen.Choose(1, 0xFD)
        from yb in Gen.Choose(1, 0xFD)
        from cx in Gen.Choose(1, 5)
        from cy in Gen.Choose(1, 5)
        from inX in Gen.Choose(2, 10)
        from inY in Gen.Choose(4, 20)
        from x in Gen.Choose(16, 100)
        from y in Gen.Choose(16, 170)
        from length in Gen.Choose(16, 40).Select(i => i / 4f)
        from cells in Gen.Choose(1, 4)
        from flips in Gen.Choose(0, 255)
        from mesh in Gen.Choose(410, 1024)
        from start in Gen.Frequency((1, Gen.Constant(0)), (2, Gen.Choose(0, 20)))
        select target == NearTarget.Building
            // The cottage's origin well inside a land cell, so the sphere's own land cell owns the building (facts §5.3).
            ? new NearTouchPlan(target, (192.0 * xb) + (24 * cx) + inX, (192.0 * yb) + (24 * cy) + inY, Math.Min(length, 8), Math.Min(cells, 2), flips, mesh, start)
            : new NearTouchPlan(target, (192.0 * xb) + x, (192.0 * yb) + y, length, Math.Max(cells, 2), flips, mesh, start);

    /// <summary>Gets hint-ahead hubs placed inside one block.</summary>
    public static Gen<HintHubPlan> Hubs { get; } =
        from xb in Gen.Choose(1, 0xFD)
        from yb in Gen.Choose(1, 0xFD)
        from x in Gen.Choose(16, 100)
        from y in Gen.Choose(16, 100)
        from size in Gen.Choose(16, 40).Select(i => i / 4f)
        from flips in Gen.Choose(0, 255)
        from mirror in Gen.Elements(true, false)
        from corner in Gen.Elements(0f, 0.25f, 0.5f, 0.75f)
        select new HintHubPlan((192.0 * xb) + x, (192.0 * yb) + y, size, flips, mirror, corner);

    /// <summary>Gets the recipes of both corners.</summary>
    public static Gen<SceneRecipe> Recipes { get; } = Gen.Frequency(
        (2, from plan in NearTouches
            select new SceneRecipe(null, null, SceneRoute.NearTouch, 0, plan.Radius, false, plan.Radius, SceneGens.Jitters[0], int.MaxValue) { NearTouch = plan }),
        (1, from hub in Hubs
            from r in Gen.Choose(12, 32).Select(i => i / 32f)
            from two in Gen.Elements(true, false)
            select new SceneRecipe(null, null, SceneRoute.HintAhead, 0, r, two, r / 2, SceneGens.Jitters[0], int.MaxValue) { HintHub = hub }));
}
