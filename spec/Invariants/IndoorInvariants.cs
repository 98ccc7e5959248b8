using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>Invariants of walks in scenes: interior wins, hysteresis, portal transit, no tunnelling, visibility, and the rest (facts §4, §5).</summary>
internal static class IndoorInvariants
{
    /// <summary>Depth, metres, beyond which a point is robustly inside or outside a cell (far above EPS and the BSP's 0.01 only where stated).</summary>
    public const double Margin = 1e-3;

    /// <summary>INTERIOR-WINS.</summary>
    public static readonly Invariant<SceneWalk> InteriorWins = new(
        "INTERIOR-WINS",
        "When a loaded env cell among the candidates contains sphere 0's centre by more than 1 mm, the containing cell is an env cell, never a land cell.",
        "facts §4 step 4b",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            bool applied = false;
            foreach (var s in SceneWalkRunner.Run(impl, w))
            {
                var c = Center(s);
                var inside = s.Cells.Select(id => SceneOracle.Cell(w.Scene, id)).FirstOrDefault(cell => cell is not null && SceneOracle.IsLoadedEnv(w.Scene, cell.Id) && SceneOracle.Pickable(cell, impl.Indoor) && SceneOracle.Depth(cell, s.Query.Cell, c) > Margin);
                if (inside is null)
                {
                    continue;
                }

                applied = true;
                if (!s.Containing.IsEnv)
                {
                    return Outcome.ViolatedAt(s.Index, $"step {s.Index}: candidate {inside.Id} contains sphere 0's centre but the containing cell is {s.Containing}");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        },
        sceneForms: SceneQueryKinds.Either);

    /// <summary>HYSTERESIS-INDOOR.</summary>
    public static readonly Invariant<SceneWalk> HysteresisIndoor = new(
        "HYSTERESIS-INDOOR",
        "With the current-cell-first pick in a scene, a current cell that is a candidate and still contains sphere 0's centre is kept (a current land cell yields only to an env cell that contains the centre), so jitter at a portal or a line switches at most once per real crossing.",
        "facts §4 step 4b; acdream's hysteresis",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            var built = SceneBuild.Build(w.Scene);
            var trace = SceneWalkRunner.Run(impl, w);
            bool applied = false;
            for (int i = 1; i < trace.Count; i++)
            {
                var s = trace[i];
                var prev = trace[i - 1].Current;
                var c = Center(s);
                if (prev.IsNone || !s.Cells.Contains(prev) || !SceneOracle.IsLoaded(w.Scene, prev) || !SceneQuery.Contains(built, s.Query.Cell, prev, c, impl.Indoor))
                {
                    continue;
                }

                // A cell without portals contains nothing under retail's point_in_cell, but does under a declared ace-no-portal-guard (facts §5.5, §7 #13).
                if (prev.IsLand && s.Cells.Any(id => id.IsEnv && SceneOracle.IsLoadedEnv(w.Scene, id) && SceneQuery.Contains(built, s.Query.Cell, id, c, impl.Indoor)))
                {
                    continue;
                }

                applied = true;
                if (s.Containing != prev)
                {
                    return Outcome.ViolatedAt(s.Index, $"step {s.Index}: current {prev} still contains sphere 0's centre but the pick moved to {s.Containing}");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        },
        PickPolicy.CurrentFirst, sceneForms: SceneQueryKinds.Either);

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

    /// <summary>VISIBILITY.</summary>
    public static readonly Invariant<SceneWalk> Visibility = new(
        "VISIBILITY",
        "For a query from a loaded env cell (LoadCells false), every loaded candidate is that cell or in its VisibleCells; only load hints may be anything else.",
        "facts §4 step 5, §6.14",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            bool applied = false;
            foreach (var s in SceneWalkRunner.Run(impl, w))
            {
                var cell = SceneOracle.Cell(w.Scene, s.Query.Cell);
                if (cell is null || !SceneOracle.IsLoadedEnv(w.Scene, cell.Id))
                {
                    continue;
                }

                if (impl.Indoor.AceEarlyReturn && s.Containing.IsEnv)
                {
                    continue; // a declared ace-early-return: after an interior pick ACE returns before the filter (facts §7 #7)
                }

                applied = true;
                for (int k = 0; k < s.Cells.Count; k++)
                {
                    var id = s.Cells[k];
                    if (id != cell.Id && !cell.Visible.Contains(id) && SceneOracle.IsLoaded(w.Scene, id) && !AceBlindHint(impl, w.Scene, s, k))
                    {
                        return Outcome.ViolatedAt(s.Index, $"step {s.Index}: from {cell.Id}, candidate {id} is loaded but not in its VisibleCells [{string.Join(", ", cell.Visible)}]");
                    }
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        },
        sceneForms: Op.FindCellScene);

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

    /// <summary>SCENE-TRANSLATION.</summary>
    public static readonly Invariant<SceneWalk> SceneTranslation = new(
        "SCENE-TRANSLATION",
        "Moving the whole scene and the walk by one landblock changes nothing but the ids: every step's candidates and containing cell are the originals moved by the same block offset (away from the map edge).",
        "facts §1.3, §5.8 (block frames are relative)",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            var blocks = w.Scene.Blocks.Concat(w.Scene.UnloadedBlocks).Append(w.Walk.StartCell.Landblock).ToList();
            int dx = blocks.Max(b => b.X) < 0xFC ? 1 : -1, dy = blocks.Max(b => b.Y) < 0xFC ? 1 : -1;
            if (blocks.Any(b => b.X + dx < 1 || b.Y + dy < 1 || b.X + dx > 0xFD || b.Y + dy > 0xFD))
            {
                return Outcome.Vacuous;
            }

            // A declared ace-load-hint-low-key keys hints by the bare 16-bit id, which no move changes (facts §7 #11); in a
            // scene holding block 0x0000 such a key cannot be told from a cell id, so the case is not judged.
            bool lowKey = impl.Indoor.AceLoadHintLowKey;
            if (lowKey && blocks.Any(b => b.X == 0 && b.Y == 0))
            {
                return Outcome.Vacuous;
            }

            CellId Moved(CellId id) => lowKey && id.IsEnv && id.BlockX == 0 && id.BlockY == 0 ? id : Move(id, dx, dy);
            var moved = new SceneWalk(w.Scene.Translated(dx, dy), w.Walk with { StartCell = Move(w.Walk.StartCell, dx, dy) });
            var a = SceneWalkRunner.Run(impl, w);
            var b = SceneWalkRunner.Run(impl, moved);
            foreach (var (x, y) in a.Zip(b))
            {
                var (wx, wy) = SceneOracle.World(x.Query.Cell, Center(x));
                if (!SceneOracle.OnMap(wx, wy, 192 + 48))
                {
                    return Outcome.Vacuous;
                }

                var expected = x.Cells.Select(Moved).ToList();
                if (!expected.SequenceEqual(y.Cells) || Move(x.Containing, dx, dy) != y.Containing)
                {
                    return Outcome.ViolatedAt(x.Index, $"step {x.Index}: moved by ({dx}, {dy}) blocks the answer is [{string.Join(", ", y.Cells)}] → {y.Containing}, expected [{string.Join(", ", expected)}] → {Move(x.Containing, dx, dy)}");
                }
            }

            return Outcome.Holds;
        },
        sceneForms: SceneQueryKinds.Either);

    /// <summary>CONTAINING-CONTAINS.</summary>
    public static readonly Invariant<SceneWalk> ContainingContains = new(
        "CONTAINING-CONTAINS",
        "The containing cell contains sphere 0's centre: an env cell's volume within 1 mm, a land cell's closed square within the 1 mm tie band.",
        "facts §4 step 4b, §5.5",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            bool applied = false;
            foreach (var s in SceneWalkRunner.Run(impl, w))
            {
                if (s.Containing.IsNone)
                {
                    continue;
                }

                applied = true;
                var c = Center(s);
                var (wx, wy) = SceneOracle.World(s.Query.Cell, c);
                bool ok = s.Containing.IsLand
                    ? Oracle.IsLandCellOnMap(s.Containing) && SceneOracle.LandDistance(s.Containing, wx, wy) <= Margin
                    : SceneOracle.Cell(w.Scene, s.Containing) is { } cell && SceneOracle.Depth(cell, s.Query.Cell, c) >= -Margin;
                if (!ok)
                {
                    return Outcome.ViolatedAt(s.Index, $"step {s.Index}: containing {s.Containing} does not contain sphere 0's centre (world {wx:R}, {wy:R}, z {c.Z:R})");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        },
        sceneForms: SceneQueryKinds.Either);

    /// <summary>NEVER-NULL.</summary>
    public static readonly Invariant<SceneWalk> NeverNull = new(
        "NEVER-NULL",
        "Every query has a containing cell, except for a documented reason: sphere 0's centre off the map, the position's own cell not loaded, over an unloaded block (unless inside the position's own env cell), in a scene with unloaded cells, outside the position's env cell after a step longer than the radius (facts §6.9) or with no sphere reaching any of its portals (it left through a wall: an env cell is left only through portals, §5.1), and while the client still holds a cell it lost for one of these reasons (retail's transition would have refused that move).",
        "facts §4 step 4b, §5.1, §6.3, §6.9",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            bool applied = false;
            var trace = SceneWalkRunner.Run(impl, w);
            var reasons = trace.Select(s => NoAnswerReason(w, s)).ToArray();
            var offTrack = OffTrack(trace, i => reasons[i]);
            for (int i = 0; i < trace.Count; i++)
            {
                var s = trace[i];
                if (offTrack[i] || reasons[i] is not null)
                {
                    continue;
                }

                applied = true;
                if (s.Containing.IsNone)
                {
                    var c = Center(s);
                    var (wx, wy) = SceneOracle.World(s.Query.Cell, c);
                    return Outcome.ViolatedAt(s.Index, $"step {s.Index}: no containing cell for sphere 0's centre at world ({wx:R}, {wy:R}, z {c.Z:R}) from {s.Query.Cell}, over loaded land");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        },
        sceneForms: SceneQueryKinds.Either);

    /// <summary>SCENE-SOUNDNESS.</summary>
    public static readonly Invariant<SceneWalk> SceneSoundness = new(
        "SCENE-SOUNDNESS",
        "Every candidate is within reach of the body: a land cell's square within r + 1 mm of a sphere centre per axis, a loaded env cell the position's own or within r + 0.01 + 1 mm of a sphere, an unloaded env cell the full id of a portal target of a loaded candidate; none twice (the array is reset per call).",
        "facts §3.2, §4 step 1, §5.1, §5.3, §5.7, §6.13",
        Op.None,
        SceneDomain.Instance,
        (impl, w) =>
        {
            foreach (var s in SceneWalkRunner.Run(impl, w))
            {
                if (Unreachable(w.Scene, s, impl.Indoor.AceLoadHintLowKey) is string why)
                {
                    return Outcome.ViolatedAt(s.Index, $"step {s.Index}: {why}");
                }
            }

            return Outcome.Holds;
        },
        sceneForms: SceneQueryKinds.Either);

    /// <summary>Gets every scene invariant.</summary>
    public static IReadOnlyList<Invariant<SceneWalk>> All { get; } =
        [InteriorWins, HysteresisIndoor, PortalTransit, NoTunnel, Visibility, EnterExit, SceneTranslation, ContainingContains, NeverNull, SceneSoundness];

    private static Vector3 Center(WalkStep s) => s.Query.Spheres[0].Center;

    // Under a declared ace-neighbour-via-visible-cells a portal neighbour missing from the walked cell's VisibleCells is
    // not resolved but added as a load hint under its id (facts §7 #10, §5.1), and the filter keeps hints (§4 step 5):
    // a candidate some loaded env cell of the block leads to by a portal without seeing it, not reported as loaded.
    private static bool AceBlindHint(ICellPhysics impl, Scene scene, WalkStep s, int k)
    {
        var id = s.Cells[k];
        if (!impl.Indoor.AceNeighbourViaVisibleCells || s.Answer?.Loaded is { } loaded && k < loaded.Count && loaded[k])
        {
            return false;
        }

        return scene.Cells.Any(c => c.Id.Landblock == id.Landblock && SceneOracle.IsLoadedEnv(scene, c.Id) && !c.Visible.Contains(id)
            && SceneOracle.LeadsTo(c, id));
    }

    // lowKey: a declared ace-load-hint-low-key, under which a load hint carries the portal's bare 16-bit id (facts §7 #11).
    private static string? Unreachable(Scene scene, WalkStep s, bool lowKey)
    {
        if (s.Cells.Distinct().Count() != s.Cells.Count)
        {
            return $"a candidate appears twice in [{string.Join(", ", s.Cells)}]";
        }

        foreach (var id in s.Cells)
        {
            bool near;
            if (id.IsLand)
            {
                near = s.Query.Spheres.Any(sp =>
                {
                    var (x, y) = SceneOracle.World(s.Query.Cell, sp.Center);
                    return SceneOracle.LandDistance(id, x, y) <= sp.Radius + Margin;
                });
            }
            else if (SceneOracle.Cell(scene, id) is { } cell && SceneOracle.IsLoadedEnv(scene, id))
            {
                near = id == s.Query.Cell || s.Query.Spheres.Any(sp => SceneOracle.Depth(cell, s.Query.Cell, sp.Center) >= -(sp.Radius + 0.01 + Margin));
            }
            else
            {
                near = id == s.Query.Cell || s.Cells.Any(c => SceneOracle.Cell(scene, c) is { } owner && (SceneOracle.LeadsTo(owner, id) || (lowKey && owner.Portals.Any(p => !p.IsExit && new CellId(p.Other) == id))));
            }

            if (!near)
            {
                return $"candidate {id} is out of the body's reach (query from {s.Query.Cell})";
            }
        }

        return null;
    }

    // NEVER-NULL's documented reasons for a query without a containing cell, or null when it must have one.
    private static string? NoAnswerReason(SceneWalk w, WalkStep s)
    {
        var c = Center(s);
        var (wx, wy) = SceneOracle.World(s.Query.Cell, c);
        bool unloadedLand = SceneOracle.LandAt(wx, wy) is not { } lc || !w.Scene.Blocks.Contains(Oracle.CellOf(lc.X, lc.Y).Landblock);
        bool inOwnCell = SceneOracle.Cell(w.Scene, s.Query.Cell) is { } own && SceneOracle.Depth(own, s.Query.Cell, c) >= Margin;
        return !SceneOracle.OnMap(wx, wy, Margin) ? "off the map"
            : !SceneOracle.IsLoaded(w.Scene, s.Query.Cell) ? "the position's cell is not loaded" // facts §4 step 4: no visible cell, no pick
            : unloadedLand && !inOwnCell ? "over an unloaded block"
            : w.Scene.UnloadedCells.Count > 0 ? "the scene has unloaded cells"
            : !ShortSteps(w) ? "a step longer than the radius" // facts §6.9
            : LeftThroughWall(w.Scene, s) ? "left the env cell through a wall" // facts §5.1: only portals lead out
            : null;
    }

    // A query from a loaded env cell whose volume no longer holds sphere 0's centre, where no transit can give it a
    // cell: the cells reachable through portal planes some sphere reaches (the side read from the geometry, as
    // LoadHintMismatch does) include no exit and none of them holds the centre by 1 mm. Retail then has nothing to answer; in
    // the game the wall's collision stops the body first. Over-approximates retail's closure (a reached plane is enough),
    // so it excuses no more than retail's own transit would.
    private static bool LeftThroughWall(Scene scene, WalkStep s)
    {
        var own = SceneOracle.Cell(scene, s.Query.Cell);
        if (own is null || !SceneOracle.IsLoadedEnv(scene, own.Id))
        {
            return false;
        }

        var seen = new HashSet<CellId> { own.Id };
        var queue = new Queue<SceneCell>([own]);
        while (queue.Count > 0)
        {
            var cell = queue.Dequeue();
            if (SceneOracle.Depth(cell, s.Query.Cell, Center(s)) >= Margin)
            {
                return false; // a reachable cell holds the centre (within the 1 mm tie band either answer is allowed)
            }

            foreach (var outward in Outward(cell))
            {
                var portal = outward.Portal;
                bool reached = s.Query.Spheres.Any(sphere => outward.Past(sphere.Center) + sphere.Radius + LandDefs.Epsilon > -Margin);
                if (!reached)
                {
                    continue;
                }

                if (portal.IsExit)
                {
                    return false; // an exit adds the land cells around the body
                }

                var next = cell.Id.WithLow(portal.Other);
                if (seen.Add(next) && SceneOracle.IsLoadedEnv(scene, next) && SceneOracle.Cell(scene, next) is { } other)
                {
                    queue.Enqueue(other);
                }
            }
        }

        return true;
    }

    // Steps queried while the client still holds a cell it lost for a documented reason (a no-answer NEVER-NULL
    // excuses): retail's transition fails on a null cell and walls stop the body, so from there until a query answers
    // again the walk is not a trajectory retail could produce, and statements about absorbing states do not apply.
    private static bool[] OffTrack(SceneWalk w, IReadOnlyList<WalkStep> trace) => OffTrack(trace, i => NoAnswerReason(w, trace[i]));

    private static bool[] OffTrack(IReadOnlyList<WalkStep> trace, Func<int, string?> noAnswerReason)
    {
        var off = new bool[trace.Count];
        bool stale = false;
        for (int i = 0; i < trace.Count; i++)
        {
            off[i] = stale;
            if (!trace[i].Containing.IsNone)
            {
                stale = false;
            }
            else if (noAnswerReason(i) is not null)
            {
                stale = true;
            }
        }

        return off;
    }

    private static bool ShortSteps(SceneWalk w) => w.Walk.Body.Count > 0 && w.Walk.Steps.All(d => d.Length() <= w.Walk.Body[0].Radius);

    private static CellId Move(CellId id, int dx, int dy) => id.IsNone ? id : new CellId((byte)(id.BlockX + dx), (byte)(id.BlockY + dy), id.Low);

    // The land cells owning a building from whose portals the target is reachable through cell portals.
    private static IEnumerable<CellId> OwnersReaching(Scene scene, CellId target) =>
        scene.Buildings.Where(b => Reaches(scene, b, target)).Select(b => new Building(b.Block, b.Origin, []).OwningCell()).Where(o => !o.IsNone);

    // The env cells a building's portals lead to, and every cell portal-linked to them (the transit closure).
    private static bool Reaches(Scene scene, SceneBuilding building, CellId target)
    {
        var seen = new HashSet<CellId>(building.Portals.Select(p => building.Block.BlockCell.WithLow(p.Cell)));
        var queue = new Queue<CellId>(seen);
        while (queue.Count > 0)
        {
            var id = queue.Dequeue();
            if (id == target)
            {
                return true;
            }

            foreach (var p in SceneOracle.Cell(scene, id)?.Portals ?? [])
            {
                if (!p.IsExit && seen.Add(id.WithLow(p.Other)))
                {
                    queue.Enqueue(id.WithLow(p.Other));
                }
            }
        }

        return false;
    }

    // Facts §5.3: a building portal with the invalid marker (portal 0xFFFF) is skipped, so it leads nowhere.
    private static bool BehindBuildingPortal(Scene scene, CellId cell) =>
        scene.Buildings.Any(b => b.Block == cell.Landblock && b.Portals.Any(p => p.Cell == cell.Low && p.Portal != BldPortal.None));

    private static bool Linked(Scene scene, CellId a, CellId b)
    {
        if (a.IsLand && b.IsLand)
        {
            var (ax, ay) = Oracle.LcoordOf(a);
            var (bx, by) = Oracle.LcoordOf(b);
            return Math.Abs(ax - bx) <= 1 && Math.Abs(ay - by) <= 1;
        }

        if (a.IsEnv && b.IsLand)
        {
            // Facts §4 step 4a: the closure runs within one query, so a step may cross two portals (a thin doorway
            // cell, 0.25 m, between a room and the exit): an exit of the cell or of a portal neighbour will do.
            return Neighbourhood(scene, a).Any(id => SceneOracle.Cell(scene, id) is { } cell && cell.Portals.Any(p => p.IsExit));
        }

        if (a.IsLand && b.IsEnv)
        {
            // facts §4 step 3: the transit closure runs within one query, so a sphere that crosses a wall into a
            // second room is entered through the first room's portals in the same call.
            return scene.Buildings.Any(bl => bl.Block == b.Landblock && Reaches(scene, bl, b));
        }

        // Facts §4 step 4a: two portals in one query (through a thin cell) — b a neighbour of a or of a neighbour of a.
        return a.Landblock == b.Landblock && Neighbourhood(scene, a).Any(m => m != a && (m == b || PortalLinked(scene, m, b)));
    }

    private static bool PortalLinked(Scene scene, CellId a, CellId b) =>
        a.Landblock == b.Landblock
        && ((SceneOracle.Cell(scene, a)?.Portals.Any(p => p.Other == b.Low) ?? false) || (SceneOracle.Cell(scene, b)?.Portals.Any(p => p.Other == a.Low) ?? false));

    // An env cell and the cells portal-linked to it.
    private static IEnumerable<CellId> Neighbourhood(Scene scene, CellId a) =>
        scene.Cells.Where(c => c.Id == a || PortalLinked(scene, a, c.Id)).Select(c => c.Id).Append(a).Distinct();

    // The position's own portals into unloaded cells, the side read from the geometry (the cell's box centre), not from
    // PortalSide. A sphere reaching past one by r + EPS gives the hint: the position is walked first (facts §4 step 3,
    // §5.1). A hint given while no sphere reaches it is wrong only if no other cell the closure may walk gives it either:
    // the transit closure walks every cell it adds, and any of them with a portal to the same unloaded cell adds the
    // same hint when a sphere reaches that portal's infinite plane (facts §4 step 4a, §5.1). Which cells were walked is
    // over-approximated by the loaded env cells of the block within r + 0.01 + 1 mm of a sphere (a neighbour or a
    // building's cell is added only when the BSP sphere test, padded 0.01, takes it in: §5.1, §5.3, §5.7; the filter
    // may drop a walked cell after its hint was added, and never drops a hint, §4 step 5), so this direction never
    // accuses a hint retail gives.
    // Under a declared ace-load-hint-low-key the hint is looked for under ACE's key, the bare 16-bit id (facts §7 #11).
    private static string? LoadHintMismatch(SceneWalk w, WalkStep s, IndoorFidelity fidelity)
    {
        var cell = SceneOracle.Cell(w.Scene, s.Query.Cell);
        if (cell is null || !SceneOracle.IsLoadedEnv(w.Scene, cell.Id))
        {
            return null;
        }

        foreach (var outward in Outward(cell))
        {
            var other = cell.Id.WithLow(outward.Portal.Other);
            if (outward.Portal.IsExit || !w.Scene.UnloadedCells.Contains(other))
            {
                continue;
            }

            var (reaches, tie) = Reach(outward, s);
            bool given = s.Cells.Contains(fidelity.AceLoadHintLowKey ? new CellId(other.Low) : other);
            if (tie || reaches == given)
            {
                continue;
            }

            if (reaches)
            {
                return $"a sphere reaches past the portal of {cell.Id} toward unloaded {other} but no load hint was given";
            }

            if (!HintedElsewhere(w.Scene, cell, other, s))
            {
                return $"load hint {other} given although every sphere is wholly on {cell.Id}'s side of the portal, and no other loaded cell's portal to it is reached";
            }
        }

        return null;
    }

    // Whether another loaded env cell the closure may have walked has a portal to the unloaded cell whose plane a sphere reaches (or ties).
    private static bool HintedElsewhere(Scene scene, SceneCell own, CellId other, WalkStep s) =>
        scene.Cells.Where(c => c.Id != own.Id && c.Id.Landblock == other.Landblock && SceneOracle.IsLoadedEnv(scene, c.Id)
                && s.Query.Spheres.Any(sp => SceneOracle.Depth(c, s.Query.Cell, sp.Center) >= -(sp.Radius + 0.01 + Margin)))
            .Any(c => Outward(c).Any(o => !o.Portal.IsExit && c.Id.WithLow(o.Portal.Other) == other && Reach(o, s) is (true, _) or (_, true)));

    // Whether a sphere reaches past a portal's plane by r + EPS, and whether one is within 1 mm of that (a tie).
    private static (bool Reaches, bool Tie) Reach(OutwardPortal outward, WalkStep s)
    {
        bool reaches = false, tie = false;
        foreach (var sphere in s.Query.Spheres)
        {
            double slack = outward.Past(sphere.Center) + sphere.Radius + LandDefs.Epsilon;
            tie |= Math.Abs(slack) < Margin;
            reaches |= slack > 0;
        }

        return (reaches, tie);
    }

    // A cell's portals with their planes normalised and the cell's own side read from the geometry (piece 0's box
    // centre), not from PortalSide, so a fault in PortalSide cannot hide itself from the invariants that use this.
    private static IEnumerable<OutwardPortal> Outward(SceneCell cell)
    {
        var frame = new Frame(cell.Origin, cell.Rotation);
        var bounds = cell.Pieces[0].ToConvex().Bounds;
        var middle = (bounds.Min + bounds.Max) / 2;
        foreach (var portal in cell.Portals)
        {
            var plane = new CellPlane(Vector3.Normalize(portal.Plane.Normal), portal.Plane.D / portal.Plane.Normal.Length());
            yield return new OutwardPortal(portal, plane, Math.Sign(plane.Distance(middle)), frame);
        }
    }

    private readonly record struct OutwardPortal(ScenePortal Portal, CellPlane Plane, double OwnSide, Frame Frame)
    {
        // How far a global point lies past the portal's plane, away from the cell (negative: on the cell's side).
        public double Past(Vector3 global) => -OwnSide * Plane.Distance(Frame.GlobalToLocal(global));
    }
}
