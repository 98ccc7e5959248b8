using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

// Moving through portals: transit, no tunnelling, in and back out (facts §4 step 4a, §5.1, §5.3).
internal static partial class IndoorInvariants
{
    /// <summary>PORTAL-TRANSIT.</summary>
    public static readonly Invariant<SceneWalk> PortalTransit = new(
        "PORTAL-TRANSIT",
        "With steps no longer than the radius: a centre inside a loaded env cell by 1 mm on two steps running is in that cell after the second (no absorbing outdoor state), except while the position is a land cell framed in another block than the cell (facts §6.11: retail does not re-frame the building test) or the cell is not directly behind a valid building portal whose building's land cell is a candidate (facts §5.3: a building is reached only through the land cell it is attached to); a centre clear of every cell on two steps running over loaded land, queried from a loaded cell, is in a land cell (no absorbing indoor state); neither clause applies while the client still holds a cell it lost for a reason NEVER-NULL excuses; and a load hint for an unloaded cell behind the position's portal appears when a sphere reaches past r + EPS toward it, and is absent when no sphere reaches that portal nor a portal of another loaded cell to the same cell (the transit closure walks those too).",
        "facts §4 step 4a, §5.1, §5.3, §5.4, §6.9, §6.11",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            if (!ShortSteps(w))
            {
                return Outcome.Vacuous;
            }

            var trace = SceneWalkRunner.Run(impl, w);
            var offTrack = OffTrack(w, trace);
            bool applied = false;
            for (int i = 0; i < trace.Count; i++)
            {
                var s = trace[i];
                var c = Center(s);
                if (LoadHintMismatch(w, s, impl.Indoor) is string hint)
                {
                    return Outcome.ViolatedAt(s.Index, $"step {s.Index}: {hint}");
                }

                if (i == 0 || offTrack[i] || offTrack[i - 1])
                {
                    continue; // see OffTrack: after an excused no-answer the walk is not a retail trajectory
                }

                var p = trace[i - 1];
                var pc = Center(p);
                var here = SceneOracle.Inside(w.Scene, s.Query.Cell, c, Margin).Where(x => SceneOracle.Pickable(x, impl.Indoor)).Select(x => x.Id).ToList();
                var before = SceneOracle.Inside(w.Scene, p.Query.Cell, pc, Margin).Where(x => SceneOracle.Pickable(x, impl.Indoor)).Select(x => x.Id).ToList();
                var both = here.Intersect(before).ToList();
                if (both.Count > 0)
                {
                    if (s.Query.Cell.IsLand && s.Query.Cell.Landblock != both[0].Landblock)
                    {
                        continue; // facts §6.11: retail tests the building with the sphere in this block's frame
                    }

                    if (s.Query.Cell.IsLand && !BehindBuildingPortal(w.Scene, both[0]))
                    {
                        continue; // from land only the cells directly behind a building's portals are entered in one query
                    }

                    if (s.Query.Cell.IsLand && !OwnersReaching(w.Scene, both[0]).Any(s.Cells.Contains))
                    {
                        continue; // facts §5.3: land reaches an env cell only through the land cell its building is attached to
                    }

                    applied = true;
                    if (!both.Contains(s.Current))
                    {
                        return Outcome.ViolatedAt(s.Index, $"step {s.Index}: sphere 0's centre has been inside {both[0]} for two steps but the current cell is {s.Current}");
                    }

                    continue;
                }

                var (wx, wy) = SceneOracle.World(s.Query.Cell, c);
                if (w.Scene.UnloadedCells.Count == 0 && SceneOracle.IsLoaded(w.Scene, s.Query.Cell)
                    && SceneOracle.OutsideAll(w.Scene, s.Query.Cell, c, Margin) && SceneOracle.OutsideAll(w.Scene, p.Query.Cell, pc, Margin)
                    && SceneOracle.OnMap(wx, wy, 1) && SceneOracle.LandAt(wx, wy) is { } lc && w.Scene.Blocks.Contains(Oracle.CellOf(lc.X, lc.Y).Landblock))
                {
                    applied = true;
                    if (!s.Current.IsLand)
                    {
                        return Outcome.ViolatedAt(s.Index, $"step {s.Index}: sphere 0's centre has been outside every cell for two steps, over loaded land, but the current cell is {s.Current}");
                    }
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        },
        sceneForms: SceneQueryKinds.Either);

    /// <summary>NO-TUNNEL.</summary>
    public static readonly Invariant<SceneWalk> NoTunnel = new(
        "NO-TUNNEL",
        "With steps no longer than the radius, the current cell changes only to a land cell of the 3 × 3 neighbourhood (from land), a portal-linked env cell or one linked to such a neighbour (from an env cell: two portals in one query, through a thin cell), a land cell (from an env cell with an exit, or next to one), or a cell behind a building portal or portal-linked to one (from land: the transit closure runs within one query); not checked while the client still holds a cell it lost for a reason NEVER-NULL excuses.",
        "facts §3.2, §5.1, §5.3",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            if (!ShortSteps(w))
            {
                return Outcome.Vacuous;
            }

            var trace = SceneWalkRunner.Run(impl, w);
            var offTrack = OffTrack(w, trace);
            bool applied = false;
            for (int i = 1; i < trace.Count; i++)
            {
                CellId a = trace[i - 1].Current, b = trace[i].Current;
                if (a.IsNone || a == b || offTrack[i])
                {
                    continue;
                }

                applied = true;
                if (!Linked(w.Scene, a, b))
                {
                    return Outcome.ViolatedAt(trace[i].Index, $"step {trace[i].Index}: the current cell jumped from {a} to {b}, which is neither a neighbour nor behind a portal");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        },
        sceneForms: SceneQueryKinds.Either);


    /// <summary>ENTER-EXIT.</summary>
    public static readonly Invariant<SceneWalk> EnterExit = new(
        "ENTER-EXIT",
        "A walk that starts outdoors clear of every cell, goes in and comes back out the same way to the same point ends in the land cell it started in (unless on the way it lost its cell for a reason NEVER-NULL excuses).",
        "facts §4 (the pick depends on the position and, with current-first, on the path only at ties)",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            if (w.Route is not SceneRoute.EnterAndBack || !ShortSteps(w))
            {
                return Outcome.Vacuous;
            }

            var trace = SceneWalkRunner.Run(impl, w);
            if (OffTrack(w, trace).Any(off => off))
            {
                return Outcome.Vacuous; // the walk lost its cell for an excused reason on the way (see OffTrack)
            }

            var first = trace[0];
            var last = trace[^1];
            var c = Center(first);
            var (wx, wy) = SceneOracle.World(first.Query.Cell, c);
            if (last.WorldX != first.WorldX || last.WorldY != first.WorldY || !first.Containing.IsLand
                || !SceneOracle.OutsideAll(w.Scene, first.Query.Cell, c, 0.05) || !SceneOracle.OnMap(wx, wy, 1)
                || Math.Abs(wx - (24 * Math.Round(wx / 24))) < Margin || Math.Abs(wy - (24 * Math.Round(wy / 24))) < Margin)
            {
                return Outcome.Vacuous;
            }

            return last.Current == first.Containing
                ? Outcome.Holds
                : Outcome.Violated($"started outdoors in {first.Containing}, walked in and back out to the same point, ended in {last.Current}");
        },
        sceneForms: SceneQueryKinds.Either);
}
