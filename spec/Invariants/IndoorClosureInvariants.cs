using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// The transit closure, exactly (facts §4 step 4a, §5.1, §5.3): complete through cell portals and building portals,
/// and sound — every env candidate has a reason. Computed from the scene description with <see cref="ExactCell"/>
/// geometry, never from the core's transit code.
/// </summary>
internal static class IndoorClosureInvariants
{
    /// <summary>NEIGHBOURS-COMPLETE.</summary>
    public static readonly Invariant<SceneWalk> NeighboursComplete = new(
        "NEIGHBOURS-COMPLETE",
        "For every loaded env candidate and every portal of it into a loaded env cell of its block, when a sphere (centre in the position's block frame, no block offset) intersects that cell's first piece by more than 1 mm under the BSP test (R = r + 0.01), the cell is a candidate — cells appended during the closure are walked too — unless the static visibility filter removes it (not the position and not in its VisibleCells) or the declared ACE lookup does not see it.",
        "facts §4 step 4a, §4 step 5, §5.1, §5.7, §6.10, §7 #10",
        Op.None,
        SceneDomain.Instance,
        (impl, w) => ExactSteps.EachStep(impl, w, (scene, s) => Neighbours(impl, scene, s)), sceneForms: SceneQueryKinds.Either);

    /// <summary>BUILDING-ENTRY-COMPLETE.</summary>
    public static readonly Invariant<SceneWalk> BuildingEntryComplete = new(
        "BUILDING-ENTRY-COMPLETE",
        "For every loaded land candidate with a building attached and every building portal with a portal index other than 0xFFFF into a loaded env cell, when a sphere (centre in the position's block frame, no block offset) intersects that cell's first piece by more than 1 mm under the BSP test, the cell is a candidate, unless the static visibility filter removes it.",
        "facts §4 step 4a, §5.3, §5.7, §6.11",
        Op.None,
        SceneDomain.Instance,
        (impl, w) => ExactSteps.EachStep(impl, w, (scene, s) => BuildingEntry(impl, scene, s)), sceneForms: SceneQueryKinds.Either);

    /// <summary>ENV-CANDIDATE-JUSTIFIED.</summary>
    public static readonly Invariant<SceneWalk> EnvCandidateJustified = new(
        "ENV-CANDIDATE-JUSTIFIED",
        "Every loaded env candidate is the position itself, or a sphere comes within 1 mm of intersecting its first piece under the BSP test (no block offset; later pieces hang under negative children, which retail never walks) and it is behind a portal of another walked env candidate or behind a building portal with a portal index other than 0xFFFF of a walked land candidate's building (after the static filter, of any loaded env cell or any reachable land cell).",
        "facts §4 step 4a, §5.1, §5.3, §5.7",
        Op.None,
        SceneDomain.Instance,
        (impl, w) => ExactSteps.EachStep(impl, w, (scene, s) => Justified(impl, scene, s)), sceneForms: SceneQueryKinds.Either);

    /// <summary>Gets the closure invariants.</summary>
    public static IReadOnlyList<Invariant<SceneWalk>> All { get; } = [NeighboursComplete, BuildingEntryComplete, EnvCandidateJustified];

    private static Outcome Neighbours(ICellPhysics impl, ExactScene scene, WalkStep s)
    {
        if (!scene.ClosureRuns(s.Query.Cell, s.Query.Spheres.Count))
        {
            return Outcome.Vacuous;
        }

        bool applied = false;
        for (int i = 0; i < s.Cells.Count; i++)
        {
            if (!s.Cells[i].IsEnv || !ExactSteps.IsLoadedEntry(scene, s, i) || scene.Env(s.Cells[i]) is not { } cell)
            {
                continue;
            }

            foreach (var portal in cell.Source.Portals)
            {
                var next = cell.Source.Id.WithLow(portal.Other);
                if (portal.IsExit || scene.Env(next) is not { } other)
                {
                    continue;
                }

                if (impl.Indoor.AceNeighbourViaVisibleCells && !cell.Source.Visible.Contains(next))
                {
                    continue; // facts §7 #10: ACE finds the neighbour only in this cell's VisibleCells
                }

                if (!ExactSteps.SurelyIntersects(impl, s, other) || !ExactSteps.SurvivesFilter(scene, s, next))
                {
                    continue;
                }

                applied = true;
                if (!s.Cells.Contains(next))
                {
                    return Outcome.Violated($"a sphere intersects {next}, behind a portal of candidate {cell.Source.Id}, but it is not a candidate [{string.Join(", ", s.Cells)}]");
                }
            }
        }

        return applied ? Outcome.Holds : Outcome.Vacuous;
    }

    private static Outcome BuildingEntry(ICellPhysics impl, ExactScene scene, WalkStep s)
    {
        if (!scene.ClosureRuns(s.Query.Cell, s.Query.Spheres.Count))
        {
            return Outcome.Vacuous;
        }

        bool applied = false;
        for (int i = 0; i < s.Cells.Count; i++)
        {
            var land = s.Cells[i];
            if (!land.IsLand || !ExactSteps.IsLoadedEntry(scene, s, i) || scene.BuildingOn(land) is not { } building)
            {
                continue;
            }

            foreach (var portal in building.Portals)
            {
                var target = land.WithLow(portal.Cell);
                if (portal.Portal == BldPortal.None || scene.Env(target) is not { } cell)
                {
                    continue; // facts §5.3: check_building_transit returns at once for portal index 0xFFFF
                }

                if (!ExactSteps.SurelyIntersects(impl, s, cell) || !ExactSteps.SurvivesFilter(scene, s, target))
                {
                    continue;
                }

                applied = true;
                if (!s.Cells.Contains(target))
                {
                    return Outcome.Violated($"a sphere intersects {target}, behind a building portal of land candidate {land}, but it is not a candidate [{string.Join(", ", s.Cells)}]");
                }
            }
        }

        return applied ? Outcome.Holds : Outcome.Vacuous;
    }

    private static Outcome Justified(ICellPhysics impl, ExactScene scene, WalkStep s)
    {
        bool ran = scene.ClosureRuns(s.Query.Cell, s.Query.Spheres.Count);
        bool filtered = ExactSteps.Filtered(s);
        var walkedEnv = new HashSet<CellId>();
        var walkedLand = new HashSet<CellId>();
        for (int i = 0; ran && i < s.Cells.Count; i++)
        {
            if (ExactSteps.IsLoadedEntry(scene, s, i))
            {
                (s.Cells[i].IsLand ? walkedLand : walkedEnv).Add(s.Cells[i]);
            }
        }

        bool applied = false;
        for (int i = 0; i < s.Cells.Count; i++)
        {
            var id = s.Cells[i];
            if (!id.IsEnv || id == s.Query.Cell || !ExactSteps.IsLoadedEntry(scene, s, i) || scene.Env(id) is not { } cell)
            {
                continue;
            }

            applied = true;
            if (!ExactSteps.MayIntersect(impl, s, cell))
            {
                return Outcome.Violated($"env candidate {id} is not the position and every sphere is clear of it by more than 1 mm");
            }

            // The static filter may have removed the cell that led here: then any loaded cell or reachable land cell may have.
            bool viaPortal = ran && (filtered ? scene.Envs : walkedEnv.Select(e => scene.Env(e)!))
                .Any(e => e.Source.Id != id && SceneOracle.LeadsTo(e.Source, id));
            bool viaBuilding = ran && scene.Attached.Any(kv => kv.Key.Landblock == id.Landblock
                && kv.Value.Portals.Any(p => p.Portal != BldPortal.None && kv.Key.WithLow(p.Cell) == id)
                && (filtered ? scene.IsLoadedLand(kv.Key) && Reaches(s, kv.Key) : walkedLand.Contains(kv.Key)));
            if (!viaPortal && !viaBuilding)
            {
                return Outcome.Violated($"env candidate {id} is behind no portal of a walked env candidate and no valid building portal of a walked land candidate's building");
            }
        }

        return applied ? Outcome.Holds : Outcome.Vacuous;
    }

    // A land cell the outdoor collection could add: its square within r + 1 mm of a sphere centre per axis (facts §3.2).
    private static bool Reaches(WalkStep s, CellId land) => s.Query.Spheres.Any(sp =>
    {
        var (x, y) = SceneOracle.World(s.Query.Cell, sp.Center);
        return SceneOracle.LandDistance(land, x, y) <= sp.Radius + IndoorInvariants.Margin;
    });
}
