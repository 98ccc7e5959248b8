using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// Indoor statements where retail is exact, beyond the closure (<see cref="IndoorClosureInvariants"/>): the interior
/// flag, leaving through exit portals, and the first-env-wins pick. Computed from the scene description.
/// </summary>
internal static class IndoorExactInvariants
{
    /// <summary>HITS-INTERIOR.</summary>
    public static readonly Invariant<SceneWalk> HitsInterior = new(
        "HITS-INTERIOR",
        "When reported, HitsInteriorCell is true exactly when the position is indoor by its low word, or some env cell is a candidate or the containing cell (from a land position env cells enter only by building entry, which sets it).",
        "facts §1.1, §4 step 3, §4 step 4b, §5.3",
        Op.None,
        SceneDomain.Instance,
        (impl, w) => ExactSteps.EachStep(impl, w, (_, s) => Hits(impl, s)), sceneForms: SceneQueryKinds.Either);

    /// <summary>LAND-VIA-EXIT.</summary>
    public static readonly Invariant<SceneWalk> LandViaExit = new(
        "LAND-VIA-EXIT",
        "In a transition query from a loaded env cell, land cells are candidates only when some sphere comes within 1 mm of straddling the infinite plane of an exit portal of a walked env candidate (−(r + EPS) < d < r + EPS, centre not offset), and when one straddles it by more than 1 mm the land cell under sphere 0's centre is a candidate (a load hint in an unloaded block, unless unloaded land cells are declared dropped).",
        "facts §3.3, §5.1, §6.9, §7 #2, §7 #12",
        Op.None,
        SceneDomain.Instance,
        (impl, w) => ExactSteps.EachStep(impl, w, (scene, s) => Exit(impl, scene, s)), sceneForms: Op.FindCellTransition);

    /// <summary>PICK-FIRST-ENV.</summary>
    public static readonly Invariant<SceneWalk> PickFirstEnv = new(
        "PICK-FIRST-ENV",
        "With the retail pick and no visibility filter, when a loaded env candidate with portals contains sphere 0's centre (re-expressed in its block frame with GetBlockOffset) by more than 1 mm in its first piece (the BSP's positive chain), the containing cell is the first such candidate in the answer's order, unless an earlier env candidate is within 1 mm of containing it; the other spheres never matter.",
        "facts §4 step 4b, §5.5, §5.7, §5.9, §6.8, §7 #13",
        Op.None,
        SceneDomain.Instance,
        (impl, w) => impl.Pick != PickPolicy.Retail ? Outcome.Vacuous : ExactSteps.EachStep(impl, w, (scene, s) => FirstEnv(impl, scene, s)), sceneForms: SceneQueryKinds.Either);

    /// <summary>Gets every exact indoor invariant, the closure's first.</summary>
    public static IReadOnlyList<Invariant<SceneWalk>> All { get; } = [.. IndoorClosureInvariants.All, HitsInterior, LandViaExit, PickFirstEnv];

    private static Outcome Hits(ICellPhysics impl, WalkStep s)
    {
        if (s.Answer?.HitsInteriorCell is not bool hits)
        {
            return Outcome.VacuousBecause("the implementation does not report hits_interior_cell");
        }

        bool indoor = s.Query.Cell.IsIndoorByLowWord; // facts §1.1: 0xFFFF counts as indoor too
        bool env = s.Containing.IsEnv || s.Cells.Any(id => id.IsEnv);
        if (hits && !indoor && !env)
        {
            return Outcome.Violated($"HitsInteriorCell is set from land position {s.Query.Cell} with no env candidate and containing cell {s.Containing}");
        }

        if (!hits && (indoor || (env && !impl.Indoor.AceKeepsStaleCells)))
        {
            // facts §7 #6: ACE's stale entries may be env cells this call did not enter.
            return Outcome.Violated(indoor
                ? $"HitsInteriorCell is clear although the position {s.Query.Cell} is indoor"
                : $"HitsInteriorCell is clear although env cells were entered from land: [{string.Join(", ", s.Cells)}] → {s.Containing}");
        }

        return Outcome.Holds;
    }

    private static Outcome Exit(ICellPhysics impl, ExactScene scene, WalkStep s)
    {
        var position = s.Query.Cell;
        if (!s.LoadCells || !position.IsEnv || !scene.ClosureRuns(position, s.Query.Spheres.Count))
        {
            return Outcome.Vacuous;
        }

        // The largest straddle slack r + EPS − |d| over every exit of every walked env candidate and every sphere.
        double slack = double.NegativeInfinity;
        bool anyExit = false;
        for (int i = 0; i < s.Cells.Count; i++)
        {
            if (!s.Cells[i].IsEnv || !ExactSteps.IsLoadedEntry(scene, s, i) || scene.Env(s.Cells[i]) is not { } cell)
            {
                continue;
            }

            for (int k = 0; k < cell.Source.Portals.Count; k++)
            {
                if (!cell.Source.Portals[k].IsExit)
                {
                    continue; // an exit is retail's flag 4, ACE's 0xFFFF: the scene sets both together (facts §7 #12)
                }

                anyExit = true;
                foreach (var sp in s.Query.Spheres)
                {
                    double d = cell.PortalDistance(k, ExactSteps.TransitPoint(impl, position, cell.Source.Id, sp.Center));
                    slack = Math.Max(slack, sp.Radius + LandDefs.Epsilon - Math.Abs(d));
                }
            }
        }

        var land = s.Cells.Where(id => id.IsLand).ToList();
        if (land.Count > 0 && slack < -IndoorInvariants.Margin && !impl.Indoor.AceKeepsStaleCells)
        {
            return Outcome.Violated($"land cells [{string.Join(", ", land)}] are candidates but no sphere straddles an exit portal of a walked env candidate (best slack {slack:R})");
        }

        if (slack > IndoorInvariants.Margin && UnderCenter(impl, scene, s) is { } under)
        {
            bool present = under.Exact is { } cell ? s.Cells.Contains(cell) : land.Any(id => SceneOracle.LandDistance(id, under.X, under.Y) <= IndoorInvariants.Margin);
            if (!present)
            {
                return Outcome.Violated($"a sphere straddles an exit portal (slack {slack:R}) but the land cell under sphere 0's centre (world {under.X:R}, {under.Y:R}) is not a candidate [{string.Join(", ", s.Cells)}]");
            }
        }

        return anyExit || land.Count > 0 ? Outcome.Holds : Outcome.Vacuous;
    }

    // The land cell add_all_outside_cells must add for sphere 0 (facts §3.3): null off the map or when the declared
    // ACE drop skips it; Exact null within 1 mm of a cell line (either side's cell will do).
    private static (double X, double Y, CellId? Exact)? UnderCenter(ICellPhysics impl, ExactScene scene, WalkStep s)
    {
        var (x, y) = SceneOracle.World(s.Query.Cell, s.Query.Spheres[0].Center);
        if (!SceneOracle.OnMap(x, y, IndoorInvariants.Margin) || SceneOracle.LandAt(x, y) is not { } lc)
        {
            return null;
        }

        var cell = Oracle.CellOf(lc.X, lc.Y);
        if (impl.Indoor.DropUnloadedLandCells && !scene.IsLoaded(cell.Landblock))
        {
            return null; // facts §7 #2: ACE skips land cells of unloaded blocks
        }

        bool nearLine = Math.Abs(x - (24 * Math.Round(x / 24))) <= IndoorInvariants.Margin || Math.Abs(y - (24 * Math.Round(y / 24))) <= IndoorInvariants.Margin;
        if (nearLine && impl.Indoor.DropUnloadedLandCells)
        {
            return null; // the neighbour across the line may be in an unloaded block
        }

        return (x, y, nearLine ? null : cell);
    }

    private static Outcome FirstEnv(ICellPhysics impl, ExactScene scene, WalkStep s)
    {
        if (ExactSteps.Filtered(s) || !scene.ClosureRuns(s.Query.Cell, s.Query.Spheres.Count))
        {
            return Outcome.Vacuous; // no pick; or the filter's swap-removal has reordered the answer since the pick (facts §5.9)
        }

        var center = s.Query.Spheres[0].Center;
        for (int i = 0; i < s.Cells.Count; i++)
        {
            var id = s.Cells[i];
            if (!id.IsEnv || !ExactSteps.IsLoadedEntry(scene, s, i) || scene.Env(id) is not { } cell)
            {
                continue;
            }

            if (!cell.HasPortals && !impl.Indoor.AceNoPortalGuard)
            {
                continue; // facts §5.5: retail's point_in_cell is false for a cell without portals
            }

            var p = center - LandDefs.GetBlockOffset(s.Query.Cell, id);
            if (cell.DepthFirst(p) > IndoorInvariants.Margin)
            {
                return s.Containing == id
                    ? Outcome.Holds
                    : Outcome.Violated($"candidate {id} is the first env candidate containing sphere 0's centre but the containing cell is {s.Containing} (candidates [{string.Join(", ", s.Cells)}])");
            }

            if (cell.DepthFirst(p) >= -LandDefs.Epsilon - IndoorInvariants.Margin)
            {
                return Outcome.Vacuous; // an earlier env candidate within the tie band
            }
        }

        return Outcome.Vacuous;
    }
}
