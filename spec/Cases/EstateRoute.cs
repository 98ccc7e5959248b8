using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The routes of estate walks: in by the entry door (always a valid building portal), through the rooms on the
/// shortest path over shared walls (past the unloaded room), out by another door; in and back; around the storey;
/// from the stairwell; or from the lead-in dungeon in the next block. Points pass only through door and wall
/// midpoints, so the walk never crosses a wall without a portal.
/// </summary>
internal static class EstateRoute
{
    /// <summary>Returns the start cell and the route's points in the start cell's block frame.</summary>
    /// <param name="r">The recipe.</param>
    /// <param name="m">The estate.</param>
    /// <returns>The start cell and points.</returns>
    public static (CellId Start, List<Vector3> Points) Points(SceneRecipe r, EstateModel m)
    {
        var plan = m.Plan;
        var home = plan.Block.BlockCell;
        switch (r.Route)
        {
            case SceneRoute.Storey when !m.StoreyId.IsNone:
                {
                    var c = m.Centres[0];
                    float w = plan.Width, d = plan.Depth, z = EstatePlan.Floor + EstatePlan.Height + 0.5f;
                    var pts = new[] { c, c + new Vector3(-w / 4, -d / 4, 0), c + new Vector3(w / 4, d * 0.3f, 0), c };
                    return (m.StoreyId, [.. pts.Select(p => m.ToBlock(p) with { Z = z })]);
                }

            case SceneRoute.Stairwell when !m.StairwellId.IsNone:
                {
                    var c = m.Centres[0];
                    float w = plan.Width;
                    // Not symmetric about the stairwell's west face (0.1 W east of c): no step lands in its tie band while the
                    // stairwell is the current cell (retail keeps it there, first env hit; facts §4 step 4b).
                    var pts = new List<Vector3> { c + new Vector3(w * 0.3f, 0, 0), c - new Vector3(w * 0.27f, 0, 0) };
                    if (m.Doors.FirstOrDefault(x => x.Room == 0) is { } door)
                    {
                        pts.Add(door.Point);
                        pts.Add(door.Outside);
                    }

                    return (m.StairwellId, [.. pts.Select(m.ToBlock)]);
                }

            default:
                break;
        }

        if (m.Doors.Count == 0)
        {
            return (home, [m.ToBlock(m.Centres[0] + new Vector3(0, -plan.Depth, 0)), m.ToBlock(m.Centres[0] + new Vector3(0, -plan.Depth - 2, 0))]);
        }

        int e = EstateKit.Entry(plan, m.Doors.Count), x = EstateKit.Exit(plan, m.Doors.Count);
        var entry = m.Doors[e];
        if (r.Route == SceneRoute.Facade)
        {
            // Even targets: the entry door's facade; odd: another free wall of the entry room (where its notch is, if any).
            var side = r.Target % 2 == 0 ? entry.Side : EstateGrid.FreeSides(m.Positions, entry.Room).FirstOrDefault(f => f != entry.Side, entry.Side);
            return (home, [.. Facade(m, entry.Room, side, m.Doors[x], r.Radius).Select(m.ToBlock)]);
        }

        var inside = new List<Vector3> { entry.Outside, entry.Point, m.Centres[entry.Room] };
        bool back = r.Route == SceneRoute.EnterAndBack, stay = r.Route == SceneRoute.Enter;
        int target = back || stay ? Math.Abs(r.Target) % m.Centres.Count : m.Doors[x].Room;
        var rooms = EstateGrid.Path(m.Positions, plan.SealedWalls, entry.Room, target, plan.UnloadedRoom) ?? [entry.Room];
        for (int i = 1; i < rooms.Count; i++)
        {
            inside.Add(m.Wall(rooms[i - 1], rooms[i]));
            inside.Add(m.Centres[rooms[i]]);
        }

        if (back)
        {
            inside.AddRange(Enumerable.Reverse(inside).Skip(1).ToList());
        }
        else if (!stay && rooms[^1] == m.Doors[x].Room)
        {
            inside.Add(m.Doors[x].Point);
            inside.Add(m.Doors[x].Outside);
        }

        var points = inside.Select(m.ToBlock).ToList();
        if (r.Route == SceneRoute.LeadIn && m.LeadCentres.Count > 0)
        {
            // The lead-in's block frame is one block west: building-block points move by +192 in x.
            var shift = new Vector3(192, 0, 0);
            var lead = m.LeadCentres.ToList();
            lead.Add(lead[^1] + new Vector3(3 + 1.5f, 0, 0));
            return (m.LeadStart, [.. lead, .. points.Select(p => p + shift)]);
        }

        return (home, points);
    }

    /// <summary>
    /// The facade walk, building frame: 2.5 m out from the midpoint of one free wall of a room, in to half a radius from
    /// it, then along the run of rooms whose wall on that side is free (toward the exit door when it is on that side of
    /// the run, else toward the longer end), to 0.4 of the end room's extent past its wall's midpoint, and 2.5 m out
    /// again. The centre stays outdoors, so every env candidate comes from building entry; a sealed wall between two
    /// doors' rooms, or a door room's notch on that side, lies under the sphere.
    /// </summary>
    private static List<Vector3> Facade(EstateModel m, int room, GridSide side, EstateDoor exit, float radius)
    {
        var at = m.Positions;
        var (back, ahead) = side is GridSide.South or GridSide.North ? (GridSide.West, GridSide.East) : (GridSide.South, GridSide.North);
        List<int> Run(GridSide dir)
        {
            var run = new List<int>();
            int j = Array.IndexOf(at, EstateGrid.Step(at[room], dir));
            while (j >= 0 && EstateGrid.FreeSides(at, j).Contains(side))
            {
                run.Add(j);
                j = Array.IndexOf(at, EstateGrid.Step(at[j], dir));
            }

            return run;
        }

        List<int> forward = Run(ahead), backward = Run(back);
        bool toExit = exit.Side == side;
        var (dir, rooms) = toExit && backward.Contains(exit.Room) ? (back, backward)
            : toExit && forward.Contains(exit.Room) ? (ahead, forward)
            : backward.Count > forward.Count ? (back, backward) : (ahead, forward);
        int end = rooms.Count == 0 ? room : toExit && rooms.Contains(exit.Room) ? exit.Room : rooms[^1];
        var outward = EstateKit.Outward(side);
        var half = outward * new Vector3(m.Plan.Width / 2, m.Plan.Depth / 2, 0);
        float extent = side is GridSide.South or GridSide.North ? m.Plan.Width : m.Plan.Depth;
        var gap = outward * (radius / 2);
        var start = m.Centres[room] + half;
        var last = m.Centres[end] + half + gap + (EstateKit.Outward(dir) * (0.4f * extent));
        return [start + (outward * 2.5f), start + gap, last, last + (outward * 2.5f)];
    }
}
