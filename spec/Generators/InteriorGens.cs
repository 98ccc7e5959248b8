using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Issue 41's indoor corners: spheres exactly at a comparison's bound in the tested cell's frame
/// (<see cref="ExactBoundPlan"/>) and interiors side by side (<see cref="SideBySidePlan"/>).
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

    /// <summary>
    /// Gets side-by-side plans: the land line between the rooms 1–7 land cells into a block, the facade 6–12 m into a land
    /// row; houses apart stand 0.125–1.5 radii apart (<see cref="SideBySidePlan.GapFraction"/>).
    /// </summary>
    public static Gen<SideBySidePlan> SideBySide { get; } =
        from layout in Gen.Elements(SideLayout.RowHouses, SideLayout.Closet, SideLayout.Apart)
        from xb in Gen.Choose(1, 0xFD)
        from yb in Gen.Choose(1, 0xFD)
        from cx in Gen.Choose(1, 7)
        from cy in Gen.Choose(0, 6)
        from inY in Gen.Choose(6 * 4, 12 * 4)
        from width in Gen.Choose(12, 32).Select(i => i / 4f)
        from depth in Gen.Choose(12, 32).Select(i => i / 4f)
        from inset in Gen.Elements(0.25f, 0.5f, 0.75f)
        from flips in Gen.Choose(0, 3)
        from gap in Gen.Elements(0.125f, 0.25f, 0.5f, 1.5f) // doors apart: below 1 − inset a body still in A reaches B; 1.5 r never does
        select new SideBySidePlan(layout, (192.0 * xb) + (24 * cx), (192.0 * yb) + (24 * cy) + (inY / 4.0), width, depth, inset, flips, gap);

    /// <summary>Gets the recipes of both corners.</summary>
    public static Gen<SceneRecipe> Recipes { get; } = Gen.Frequency(
        (1, from plan in ExactBounds
            select new SceneRecipe(null, null, SceneRoute.ExactBound, 0, plan.Radius, false, plan.Radius, SceneGens.Jitters[0], int.MaxValue) { Plan = plan }),
        (1, from plan in SideBySide
            from r in Gen.Choose(12, 32).Select(i => i / 32f)
            from two in Gen.Elements(true, false)
            from stepFraction in Gen.Elements(0.25f, 0.5f)
            select new SceneRecipe(null, null, SceneRoute.SideBySide, 0, r, two, r * stepFraction, SceneGens.Jitters[0], int.MaxValue) { Plan = plan }));
}
