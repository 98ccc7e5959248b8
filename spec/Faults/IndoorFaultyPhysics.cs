using System.Numerics;
using System.Runtime.CompilerServices;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// The reference scene query with one indoor defect in place, so the core itself has no fault switches: the first
/// faults are built from core's public steps (transit, pick, filter), a port's faults (<see cref="IndoorPortFaults"/>)
/// run <see cref="FaultySceneQuery"/>. Reports load-hint flags and HitsInteriorCell as the buggy code computes them,
/// answers transition queries, and delegates open land to the reference.
/// </summary>
internal sealed class IndoorFaultyPhysics(PlantedFault fault) : ICellPhysics
{
    private readonly ConditionalWeakTable<Scene, CellScene> built = [];
    private readonly CellArray array = new();
    private readonly bool portFault = IndoorPortFaults.All.Contains(fault);

    public string Name => "reference+" + fault.Id;

    public Op Ops => Op.All;

    public PickPolicy Pick => fault == IndoorFaults.NoHysteresisIndoor ? PickPolicy.CurrentFirst : PickPolicy.Retail;

    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => ReferenceAdapter.Instance.BlockIdToLcoord(id, out lcoord);

    public bool GidToLcoord(CellId id, out Lcoord lcoord) => ReferenceAdapter.Instance.GidToLcoord(id, out lcoord);

    public CellId LcoordToGid(int x, int y) => ReferenceAdapter.Instance.LcoordToGid(x, y);

    public bool InboundValidCellId(CellId id) => ReferenceAdapter.Instance.InboundValidCellId(id);

    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => ReferenceAdapter.Instance.GetOutsideLcoord(id, x, y, out lcoord);

    public AdjustResult AdjustToOutside(CellId id, float x, float y) => ReferenceAdapter.Instance.AdjustToOutside(id, x, y);

    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => ReferenceAdapter.Instance.OutsideCells(cell, spheres);

    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => ReferenceAdapter.Instance.FindCell(cell, spheres, current);

    public IReadOnlyList<CellId> OutsideCells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres) => ReferenceAdapter.Instance.OutsideCells(cell, origin, spheres);

    public FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) => ReferenceAdapter.Instance.FindCell(cell, origin, spheres, current);

    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => ReferenceAdapter.Instance.OutsideCellsParts(parts);

    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(scene, cell, spheres, current, false);

    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells)
    {
        if (scene is null)
        {
            return ReferenceAdapter.Instance.FindCell(null, cell, spheres, current, loadCells);
        }

        var core = built.GetValue(scene, Build);
        Sphere[] s = [.. spheres];
        var result = portFault
            ? FaultySceneQuery.FindCellList(array, core, cell, s, loadCells, IndoorPortFaults.DefectOf(fault))
            : FirstFaults(core, cell, s, current, loadCells);
        return new FindCellResult(array.ToIdArray(), result.Containing) { Loaded = LoadedFlags(), HitsInteriorCell = result.HitsInteriorCell };
    }

    // The sphere-path faults leave the parts variant as the reference answers it.
    public FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) => ReferenceAdapter.Instance.FindCellParts(scene, parts, loadCells);

    private CellScene Build(Scene scene)
    {
        var data = FaultyScenes.Transform(fault, scene);
        return IndoorPortFaults.VolumeOf(fault) is { } wrap ? FaultySceneBuild.Build(data, wrap) : SceneBuild.Build(data);
    }

    private CellQueryResult FirstFaults(CellScene scene, CellId cell, Sphere[] s, CellId current, bool loadCells)
    {
        var fidelity = new IndoorFidelity(AceKeepsStaleCells: fault == IndoorFaults.StaleSceneArray, AceLoadHintLowKey: fault == IndoorFaults.AceHintKey);
        if (fault != IndoorFaults.StaleSceneArray || array.Count > 64)
        {
            array.Reset(); // stale-scene-array: bound the stale growth; still far from a per-call reset
        }

        bool customPick = fault == IndoorFaults.OutdoorWins || fault == IndoorFaults.NoReframe;
        bool noFilter = loadCells || fault == IndoorFaults.NoVisibilityFilter;
        var options = new CellQueryOptions(PickPolicy.Retail, !customPick, noFilter || customPick, fidelity);
        var result = SceneQuery.FindCellList(array, scene, cell, s, current, options);
        var containing = result.Containing;
        bool hits = result.HitsInteriorCell;
        if (customPick)
        {
            bool visible = cell.IsIndoorByLowWord ? scene.GetEnvCell(cell) is not null : cell.IsLand && scene.IsLoaded(cell.Landblock);
            containing = visible && s.Length > 0 ? PickFaulty(scene, cell, s[0].Center) : CellId.None;
            hits |= containing.IsEnv;
            if (cell.IsIndoorByLowWord && visible && s.Length > 0 && !noFilter)
            {
                SceneQuery.FilterVisible(array, scene, cell);
            }
        }

        if (fault == IndoorFaults.KeepCurrentOnMiss && containing.IsNone)
        {
            containing = current;
        }

        return new CellQueryResult(containing, hits);
    }

    private bool[] LoadedFlags()
    {
        var flags = new bool[array.Count];
        for (int i = 0; i < flags.Length; i++)
        {
            flags[i] = array[i].Loaded;
        }

        return flags;
    }

    private CellId PickFaulty(CellScene scene, CellId position, Vector3 center)
    {
        CellId land = CellId.None, env = CellId.None;
        for (int i = 0; i < array.Count; i++)
        {
            var e = array[i];
            if (!e.Loaded)
            {
                continue;
            }

            // no-reframe: the candidate's own block frame is taken to be the position's.
            var frame = fault == IndoorFaults.NoReframe ? e.Id : position;
            if (!SceneQuery.Contains(scene, frame, e.Id, center, default))
            {
                continue;
            }

            if (e.Id.IsLand)
            {
                land = e.Id;
            }
            else if (env.IsNone)
            {
                env = e.Id;
            }
        }

        // outdoor-wins: the last land hit beats every env hit; no-reframe keeps retail's order (first env hit, else last land hit).
        return fault == IndoorFaults.OutdoorWins ? (land.IsNone ? env : land) : (env.IsNone ? land : env);
    }
}
