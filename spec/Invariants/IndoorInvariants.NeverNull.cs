using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

// The documented reasons for no containing cell, and the walk off retail's track after one (facts §4 step 4b, §5.1, §6.9).
internal static partial class IndoorInvariants
{
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
}
