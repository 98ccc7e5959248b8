using System.Globalization;
using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Cases;

/// <summary>
/// How a generated scene walk is built: a cottage or a dungeon, a route, a body and a step length. The shrinker
/// simplifies recipes (fewer rooms, no yaw, no flips, fewer steps) and rebuilds the scene and walk from them.
/// </summary>
/// <param name="Cottage">The cottage, or null.</param>
/// <param name="Dungeon">The dungeon, or null.</param>
/// <param name="Route">The route.</param>
/// <param name="Target">Target room (or portal index for jitter).</param>
/// <param name="Radius">Sphere radius.</param>
/// <param name="TwoSpheres">Whether a second sphere sits 0.7 m above the first.</param>
/// <param name="StepMax">Longest step, metres.</param>
/// <param name="Jitter">Jitter amplitude, metres.</param>
/// <param name="Take">Steps kept (the shrinker cuts the tail).</param>
public sealed record SceneRecipe(CottagePlan? Cottage, DungeonPlan? Dungeon, SceneRoute Route, int Target, float Radius, bool TwoSpheres, float StepMax, float Jitter, int Take) : ISceneRecipe
{
    /// <summary>Gets the estate, or null (when set, it takes the place of the cottage and the dungeon).</summary>
    public EstatePlan? Estate { get; init; }

    /// <summary>Gets the hub, or null (when set, it takes the place of the cottage and the dungeon).</summary>
    public HubPlan? Hub { get; init; }

    /// <summary>Gets the number of spheres (1 to 3, at heights 0.6, 1.3, 1.9 m) with their own radii; 0 = <see cref="TwoSpheres"/> decides.</summary>
    public int Spheres { get; init; }

    /// <summary>Gets sphere 1's radius (with <see cref="Spheres"/> ≥ 2).</summary>
    public float Radius1 { get; init; }

    /// <summary>Gets sphere 2's radius (with <see cref="Spheres"/> = 3).</summary>
    public float Radius2 { get; init; }

    /// <summary>Gets the near-touch plan, or null (when set, it builds the whole case).</summary>
    public NearTouchPlan? NearTouch { get; init; }

    /// <summary>Gets the hint-ahead hub, or null (when set, it builds the whole case).</summary>
    public HintHubPlan? HintHub { get; init; }

    /// <summary>Gets a plan that builds the whole case (issue 41), or null.</summary>
    public ISceneWalkPlan? Plan { get; init; }

    /// <summary>Gets the shape class of the scene, for distributions.</summary>
    public string Shape => Plan is { } plan ? plan.Shape : NearTouch is { } n ? (n.Target == NearTarget.Building ? $"cottage-{Math.Clamp(n.Cells, 1, 2)}" : $"dungeon-{Math.Max(2, n.Cells)}") : HintHub is not null ? "dungeon-hub" : Hub is not null ? "hub" : Estate is { } e ? $"estate-{e.Layout.ToString().ToLowerInvariant()}-{e.Rooms}" : Cottage is { } c ? $"cottage-{c.Rooms}{(c.Storey ? "+storey" : string.Empty)}" : $"dungeon-{Dungeon!.Cells}";

    /// <summary>Builds the case.</summary>
    /// <returns>The scene walk.</returns>
    public SceneWalk Build()
    {
        if (Plan is { } whole)
        {
            return whole.Build(this);
        }

        if (NearTouch is { } near)
        {
            return near.Build(this);
        }

        if (HintHub is { } hintHub)
        {
            return hintHub.Build(this);
        }

        var model = Estate is { } e ? EstateKit.Build(e) : null;
        var scene = model?.Scene ?? (Hub is { } h ? HubKit.Build(h) : Cottage is { } c ? SceneKit.Cottage(c) : SceneKit.Dungeon(Dungeon!));
        var (startCell, points) = model is not null ? EstateRoute.Points(this, model) : Hub is { } hub ? (hub.QuadrantId(0), HubKit.Route(hub)) : Cottage is { } plan ? CottageRoute(plan) : DungeonRoute(Dungeon!);
        var steps = new List<Vector2>();
        float total = 0;
        for (int i = 1; i < points.Count; i++)
        {
            total += Vector2.Distance(new Vector2(points[i].X, points[i].Y), new Vector2(points[i - 1].X, points[i - 1].Y));
        }

        float stepMax = Math.Min(Radius, Math.Max(StepMax, total / 96)); // at most ~100 steps per walk
        for (int i = 1; i < points.Count; i++)
        {
            var d = new Vector2(points[i].X - points[i - 1].X, points[i].Y - points[i - 1].Y);
            // A power of two, so that d / n is exact whenever d is (jitter walks return exactly to the line).
            int n = (int)System.Numerics.BitOperations.RoundUpToPowerOf2((uint)Math.Max(1, (int)MathF.Ceiling(d.Length() / stepMax)));
            for (int k = 0; k < n; k++)
            {
                steps.Add(d / n);
            }
        }

        if (model is null && Cottage is { LoadNeighbours: false } unloaded && LeavesBlock(points[0], steps.Take(Take)))
        {
            // A client always has the blocks around it loaded, so a walk whose centre crosses into an unloaded
            // neighbour block is outside the model (leaving a room through its door onto unloaded land, the body is
            // lost for good: NEVER-NULL, PORTAL-TRANSIT on the reference). Such a recipe is built with its neighbours
            // loaded. Found by the scene fuzz target (a yawed cottage 1 m short of a block line, door facing it).
            return (this with { Cottage = unloaded with { LoadNeighbours = true } }).Build();
        }

        // Likewise a walk has no business off the map: a cottage at the west edge, yawed so that its rooms overhang the
        // edge, walked through and out of its back door onto no land is lost for good. The walk stops before its centre
        // would leave the map (found by the scene fuzz target).
        var home = model is not null || Hub is not null ? startCell.Landblock : Cottage?.Block ?? Dungeon!.Block;
        int take = Math.Min(Take, OnMapSteps(new Vector2(192f * home.X, 192f * home.Y), points[0], steps));

        BodySphere[] body = Spheres > 0
            ? [.. new[] { new BodySphere(new Vector3(0, 0, 0.6f), Radius), new BodySphere(new Vector3(0, 0, 1.3f), Radius1), new BodySphere(new Vector3(0, 0, 1.9f), Radius2) }.Take(Math.Min(Spheres, 3))]
            : TwoSpheres
            ? [new BodySphere(new Vector3(0, 0, 0.6f), Radius), new BodySphere(new Vector3(0, 0, 1.3f), Radius)]
            : [new BodySphere(new Vector3(0, 0, 0.6f), Radius)];
        var walk = new Walk(startCell, points[0], body, [.. steps.Take(take)]);
        if (!startCell.IsEnv)
        {
            walk = walk.Normalised();
        }

        return new SceneWalk(scene, walk) { Recipe = this };
    }

    /// <inheritdoc/>
    public override string ToString() =>
        string.Create(CultureInfo.InvariantCulture, $"{Shape} {Route} target {Target} r={Radius}{(Spheres > 0 ? $" spheres {Spheres} r1={Radius1} r2={Radius2}" : TwoSpheres ? " x2" : string.Empty)} step≤{StepMax} jitter {Jitter} take {Take}") +
        (Plan is { } pl ? " " + pl
        : NearTouch is { } n ? " " + n
        : HintHub is { } hh ? " " + hh
        : Hub is { } hb ? " " + hb
        : Estate is { } e ? " " + e
        : Cottage is { } c
            ? string.Create(CultureInfo.InvariantCulture, $" at ({c.WorldX:R}, {c.WorldY:R}) yaw {c.Yaw} {c.Width}x{c.Depth} flips {c.Flips}{(c.BackDoor ? " back-door" : string.Empty)}{(c.LoadNeighbours ? string.Empty : " neighbours-unloaded")}{(c.Closet ? " closet" : string.Empty)}")
            : string.Create(CultureInfo.InvariantCulture, $" at ({Dungeon!.WorldX:R}, {Dungeon.WorldY:R}) length {Dungeon.Length} unloaded {Dungeon.Unloaded} flips {Dungeon.Flips}"));

    private (CellId Start, List<Vector3> Points) CottageRoute(CottagePlan p)
    {
        float w = p.Width, d = p.Depth;
        int target = Math.Clamp(Target, 0, p.Rooms - 1);
        var outside = new Vector3(w / 2, -2.5f, 0);
        var door = new Vector3(w / 2, 0, 0);
        var inRoom0 = new Vector3(w / 2, d / 2, 0);
        var path = new List<Vector3> { outside, door, inRoom0 };
        for (int i = 1; i <= target; i++)
        {
            path.Add(new Vector3((i + 0.5f) * w, d / 2, 0));
        }

        var start = p.Block.BlockCell;
        switch (Route)
        {
            case SceneRoute.EnterAndBack:
                path.AddRange(Enumerable.Reverse(path).Skip(1).ToList());
                break;
            case SceneRoute.Through:
                int last = p.Rooms - 1;
                for (int i = target + 1; i <= last; i++)
                {
                    path.Add(new Vector3((i + 0.5f) * w, d / 2, 0));
                }

                path.Add(new Vector3((last + 0.5f) * w, d + 2.5f, 0));
                break;
            case SceneRoute.PortalJitter:
                // Target 0: the front door; k > 0: the door between rooms k−1 and k.
                var (approach, plane, normal) = Target % p.Rooms == 0
                    ? (door - new Vector3(0, 1.5f, 0), door, Vector3.UnitY)
                    : (new Vector3(((Target % p.Rooms) - 0.5f) * w, d / 2, 0), new Vector3((Target % p.Rooms) * w, d / 2, 0), Vector3.UnitX);
                path = [approach, plane];
                if (Target % p.Rooms != 0)
                {
                    start = p.RoomId((Target % p.Rooms) - 1); // an inner door: start in the room before it
                }

                for (int i = 0; i < 6; i++)
                {
                    path.Add(plane + (normal * (i % 2 == 0 ? Jitter : -Jitter)));
                }

                path.Add(plane + (normal * 2f));
                break;
            case SceneRoute.LineJitter:
                // Jitter across the 24 m line nearest the front door, outdoors in front of the cottage.
                var world = p.ToBlock(outside);
                var local = new Vector3(LineNear(p, world), world.Y, 0);
                path = [local];
                for (int i = 0; i < 6; i++)
                {
                    path.Add(local + new Vector3(i % 2 == 0 ? Jitter : -Jitter, 0, 0));
                }

                return (start, path);
            case SceneRoute.Closet:
                // Outside the closet's south wall, into its middle, back out: the centre is inside a cell without portals.
                float cx = -CottagePlan.ClosetWidth / 2, cy = MathF.Min(d, 4f) / 2;
                path = [new Vector3(cx, -2.5f, 0), new Vector3(cx, cy, 0), new Vector3(cx, -2.5f, 0)];
                break;
            case SceneRoute.Storey:
                start = p.RoomId(p.Rooms);
                path = [new Vector3(w / 2, d / 2, CottagePlan.Height), new Vector3(w * 0.25f, d * 0.25f, CottagePlan.Height), new Vector3(w * 0.75f, d * 0.8f, CottagePlan.Height)];
                break;
            default:
                break;
        }

        return (start, [.. path.Select(p.ToBlock)]);
    }

    // How many leading steps keep the walk's centre on the map (start and steps in the home block's frame).
    private static int OnMapSteps(Vector2 blockOrigin, Vector3 start, List<Vector2> steps)
    {
        const double edge = 192.0 * (LandDefs.MaxBlockByte + 1), margin = 1.0 / 64;
        double x = blockOrigin.X + (double)start.X, y = blockOrigin.Y + (double)start.Y;
        for (int i = 0; i < steps.Count; i++)
        {
            x += steps[i].X;
            y += steps[i].Y;
            if (x < margin || y < margin || x >= edge - margin || y >= edge - margin)
            {
                return i;
            }
        }

        return steps.Count;
    }

    // Whether the walk's centre, from start (home block frame) through the steps, ever leaves the home block.
    private static bool LeavesBlock(Vector3 start, IEnumerable<Vector2> steps)
    {
        var p = new Vector2(start.X, start.Y);
        static bool Outside(Vector2 q) => q.X < 0 || q.Y < 0 || q.X >= 192 || q.Y >= 192;
        if (Outside(p))
        {
            return true;
        }

        foreach (var d in steps)
        {
            p += d;
            if (Outside(p))
            {
                return true;
            }
        }

        return false;
    }

    // The x of the 24 m line nearest a block-frame point such that the line's crossing (and the jitter around it) stays
    // clear of the cottage's footprint: with yaw, the nearest line can fall inside a room or on a wall, and a walk
    // that starts there steps through the wall (no portal), which no client can do. Found by the scene fuzz target
    // (a quarter-turned cottage whose back wall lies on the line: NEVER-NULL and PORTAL-TRANSIT on the reference).
    private float LineNear(CottagePlan p, Vector3 world)
    {
        int nearest = (int)MathF.Round(world.X / 24f);
        var frame = new Frame(p.Origin, p.Rotation);
        float margin = Radius + Jitter + 0.25f;
        bool Clear(float x)
        {
            var q = frame.GlobalToLocal(new Vector3(x, world.Y, 0));
            return q.X < -margin || q.X > (p.Rooms * p.Width) + margin || q.Y < -margin || q.Y > p.Depth + margin;
        }

        foreach (int k in new[] { 0, -1, 1, -2, 2, -3, 3 }.Select(d => nearest + d).OrderBy(k => MathF.Abs((24f * k) - world.X)))
        {
            double worldX = (192.0 * p.Block.X) + (24.0 * k);
            if (Clear(24f * k) && (k == nearest || worldX is >= 24 and <= (192.0 * 0xFF) - 24))
            {
                return 24f * k;
            }
        }

        return world.X; // no clear line nearby: jitter in front of the door, where the walk is outdoors
    }

    private (CellId Start, List<Vector3> Points) DungeonRoute(DungeonPlan p)
    {
        var origin = p.Origin;
        var path = new List<Vector3> { origin + new Vector3(p.Length / 2, SceneKit.DungeonWidth / 2, 0), origin + new Vector3((p.Cells * p.Length) + 2.5f, SceneKit.DungeonWidth / 2, 0) };
        if (Route == SceneRoute.DungeonRunAndBack)
        {
            path.Add(path[0]);
        }

        return (p.Block.BlockCell.WithLow(0x100), path);
    }
}
