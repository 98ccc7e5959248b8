using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Cases;

/// <summary>What a near-touch walk's sphere nearly touches (issue 27, facts §6.10: each test pads differently).</summary>
public enum NearTarget
{
    /// <summary>A loaded portal neighbour's volume: sphere_intersects_cell, radius unpadded, the BSP's +0.01 (facts §5.1, §5.7).</summary>
    Neighbour,

    /// <summary>A building's room from outside: check_building_transit, radius unpadded, the BSP's +0.01 (facts §5.3, §5.7).</summary>
    Building,

    /// <summary>An exit portal's plane: −R &lt; d &lt; R with R = r + EPS (facts §5.1).</summary>
    ExitPlane,

    /// <summary>An unloaded neighbour's portal plane: the load-hint side test, R = r + EPS (facts §5.1, §5.4).</summary>
    HintPlane,
}

/// <summary>
/// A near-touch walk (issue 27, corner A): one sphere placed at gaps r + g from a plane that decides a membership test,
/// for g = 0.03, 0.015, 0.01 + EPS/2, 0.01 ± 1 ulp, EPS ± 1 ulp, 0.005, EPS/2, 0, −EPS/2, −0.005 and, around the test's
/// own threshold (found with the reference's own float32 test), ±3 ulps. Differences within 8 ulps of a threshold are
/// numerical ties the conformance judge excuses in scenes (docs/conformance.md); the EPS/2 and 0.005 gaps are not. The radius is chosen so that the threshold r + pad is a multiple of
/// 1/1024 m: the exact tie (distance == r + pad) is reachable, so `&lt;` against `&lt;=` shows. Scenes are axis-aligned
/// (no yaw), every coordinate exact; the walk starts at <see cref="StartAt"/>'s position (a fresh static query there)
/// and visits the others in turn.
/// </summary>
/// <param name="Target">The test.</param>
/// <param name="WorldX">Origin, world x (whole metres).</param>
/// <param name="WorldY">Origin, world y (whole metres).</param>
/// <param name="Length">Dungeon cell length / cottage room side, metres (a multiple of 1/4).</param>
/// <param name="Cells">Dungeon cells (2–4) or cottage rooms (1–2).</param>
/// <param name="Flips">Bit i flips portal i's plane (PortalSide false instead of true).</param>
/// <param name="Mesh">The threshold r + pad is Mesh / 1024 m.</param>
/// <param name="StartAt">Which position the walk starts at (the list is rotated).</param>
public sealed record NearTouchPlan(NearTarget Target, double WorldX, double WorldY, float Length, int Cells, int Flips, int Mesh, int StartAt)
{
    /// <summary>Gets the padding the target's own test adds: the BSP's 0.01 or the portal planes' EPS (facts §1.5).</summary>
    public float Pad => Target is NearTarget.Neighbour or NearTarget.Building ? 0.01f : LandDefs.Epsilon;

    /// <summary>Gets the radius: the float32 r with r + <see cref="Pad"/> == Mesh / 1024 exactly.</summary>
    public float Radius
    {
        get
        {
            float t = Mesh / 1024f, r = t - Pad;
            for (int k = 0; k < 16 && r + Pad != t; k++)
            {
                r = r + Pad < t ? MathF.BitIncrement(r) : MathF.BitDecrement(r);
            }

            return r;
        }
    }

    /// <summary>Builds the scene walk.</summary>
    /// <param name="recipe">The recipe carrying this plan (its Take applies).</param>
    /// <returns>The case.</returns>
    public SceneWalk Build(SceneRecipe recipe)
    {
        float r = Radius;
        var (scene, start, plane, along, other) = Layout();
        var cs = SceneBuild.Build(scene);
        var body = new BodySphere(new Vector3(0, 0, 0.6f), r);
        Vector3 At(float v) => along == 0 ? new Vector3(v, other, 0) : new Vector3(other, v, 0);
        bool Reaches(float v) => ReachesAt(cs, start, At(v) + body.Offset, r);

        // The threshold: the innermost coordinate whose sphere does not reach (every retail test is false at the tie).
        float eq = plane - (Mesh / 1024f);
        for (int k = 0; k < 64 && Reaches(eq); k++)
        {
            eq = MathF.BitDecrement(eq);
        }

        for (int k = 0; k < 64 && !Reaches(MathF.BitIncrement(eq)); k++)
        {
            eq = MathF.BitIncrement(eq);
        }

        var coords = new SortedSet<float> { plane - (r + 0.03f) };
        float ulps = eq;
        for (int k = 0; k < 3; k++)
        {
            ulps = MathF.BitDecrement(ulps);
        }

        for (int k = -3; k <= 3; k++, ulps = MathF.BitIncrement(ulps))
        {
            coords.Add(ulps);
        }

        float otherPad = plane - (r + (Pad == 0.01f ? LandDefs.Epsilon : 0.01f));
        coords.UnionWith([MathF.BitDecrement(otherPad), otherPad, MathF.BitIncrement(otherPad)]);
        foreach (float g in new[] { 0.015f, 0.01f + (LandDefs.Epsilon / 2), 0.005f, LandDefs.Epsilon / 2, 0f, -LandDefs.Epsilon / 2, -0.005f })
        {
            coords.Add(plane - (r + g));
        }

        var list = coords.ToList();
        int s = Math.Clamp(StartAt, 0, list.Count - 1);
        list = [.. list.Skip(s), .. list.Take(s)];
        var steps = new List<Vector2>();
        for (int i = 1; i < list.Count; i++)
        {
            float d = list[i] - list[i - 1]; // exact (Sterbenz): the walk's float32 sum lands on list[i]
            steps.Add(along == 0 ? new Vector2(d, 0) : new Vector2(0, d));
        }

        var walk = new Walk(start, At(list[0]), [body], [.. steps.Take(recipe.Take)]);
        return new SceneWalk(scene, start.IsEnv ? walk : walk.Normalised()) { Recipe = recipe };
    }

    /// <inheritdoc/>
    public override string ToString() =>
        FormattableString.Invariant($"near {Target} at ({WorldX:R}, {WorldY:R}) length {Length} cells {Cells} flips {Flips} mesh {Mesh} start {StartAt}");

    // Whether the target's retail test (float32, as the reference computes it) says the sphere reaches.
    private bool ReachesAt(CellScene cs, CellId start, Vector3 c, float r)
    {
        var block = start.Landblock.BlockCell;
        switch (Target)
        {
            case NearTarget.Neighbour:
            case NearTarget.Building:
                var room = cs.GetEnvCell(block.WithLow((ushort)(Target == NearTarget.Neighbour ? 0x101 : 0x100)))!;
                return room.Volume.SphereIntersects(new Sphere(room.Frame.GlobalToLocal(c), r)) != BoundingType.Outside;
            default:
                var cell = cs.GetEnvCell(start)!;
                var portal = cell.Portals[^1];
                float d = portal.Plane.Distance(cell.Frame.GlobalToLocal(c)), big = r + LandDefs.Epsilon;
                return Target == NearTarget.ExitPlane ? d > -big && d < big : portal.PortalSide ? d > -big : d < big;
        }
    }

    // The scene, the start cell, the plane's coordinate along the walked axis (block frame), the axis, the other coordinate.
    private (Scene Scene, CellId Start, float Plane, int Along, float Other) Layout()
    {
        if (Target == NearTarget.Building)
        {
            var c = new CottagePlan(WorldX, WorldY, 0f, Math.Clamp(Cells, 1, 2), Length, Length, Flips, false, false);
            return (SceneKit.Cottage(c), c.Block.BlockCell, c.Origin.Y, 1, c.Origin.X + 1);
        }

        int n = Math.Max(2, Cells);
        var d = new DungeonPlan(WorldX, WorldY, n, Length, Target == NearTarget.HintPlane ? 1 : 0, Flips);
        var block = d.Block.BlockCell;
        var (cell, wall) = Target switch
        {
            NearTarget.Neighbour => (0, 1),
            NearTarget.ExitPlane => (n - 1, n),
            _ => (n - 2, n - 1), // the last loaded cell; its last portal leads to the unloaded tail
        };
        return (SceneKit.Dungeon(d), block.WithLow((ushort)(0x100 + cell)), d.Origin.X + (wall * Length), 0, d.Origin.Y + (SceneKit.DungeonWidth / 2));
    }
}
