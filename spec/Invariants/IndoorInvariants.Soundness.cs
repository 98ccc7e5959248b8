using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

// What a candidate may be: seen from the position (VISIBILITY), within the body's reach (SCENE-SOUNDNESS).
internal static partial class IndoorInvariants
{
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
}
