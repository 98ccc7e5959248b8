using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

// The pick: which candidate is the containing cell (facts §4 step 4b).
internal static partial class IndoorInvariants
{
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
}
