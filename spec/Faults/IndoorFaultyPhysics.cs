using System.Numerics;
using System.Runtime.CompilerServices;
using AcPhys.Core;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Faults;

/// <summary>
/// The reference scene query with one indoor defect in place, built from core's public steps (transit, pick,
/// filter) so the core itself has no fault switches. Offers only <see cref="Op.FindCellScene"/>.
/// </summary>
internal sealed class IndoorFaultyPhysics(PlantedFault fault) : ICellPhysics
{
    private readonly ConditionalWeakTable<Scene, Scene> transformed = [];
    private readonly CellArray array = new();

    public string Name => "reference+" + fault.Id;

    public Op Ops => Op.All | Op.FindCellScene;

    public PickPolicy Pick => fault == IndoorFaults.NoHysteresisIndoor ? PickPolicy.CurrentFirst : PickPolicy.Retail;

    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => ReferenceAdapter.Instance.BlockIdToLcoord(id, out lcoord);

    public bool GidToLcoord(CellId id, out Lcoord lcoord) => ReferenceAdapter.Instance.GidToLcoord(id, out lcoord);

    public CellId LcoordToGid(int x, int y) => ReferenceAdapter.Instance.LcoordToGid(x, y);

    public bool InboundValidCellId(CellId id) => ReferenceAdapter.Instance.InboundValidCellId(id);

    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => ReferenceAdapter.Instance.GetOutsideLcoord(id, x, y, out lcoord);

    public AdjustResult AdjustToOutside(CellId id, float x, float y) => ReferenceAdapter.Instance.AdjustToOutside(id, x, y);

    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => ReferenceAdapter.Instance.OutsideCells(cell, spheres);

    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(null, cell, spheres, current);

    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => ReferenceAdapter.Instance.OutsideCellsParts(parts);

    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current)
    {
        if (fault == IndoorFaults.InvertedPortalSide && scene is not null)
        {
            scene = transformed.GetValue(scene, s => s with { Cells = [.. s.Cells.Select(c => c with { Portals = [.. c.Portals.Select(p => p with { PortalSide = !p.PortalSide })] })] });
        }

        if (fault == IndoorFaults.NoExitTransit && scene is not null)
        {
            scene = transformed.GetValue(scene, s => s with { Cells = [.. s.Cells.Select(c => c with { Portals = [.. c.Portals.Where(p => !p.IsExit)] })] });
        }

        var built = scene is null ? CellScene.Open : SceneBuild.Build(scene);
        var fidelity = new IndoorFidelity(AceKeepsStaleCells: fault == IndoorFaults.StaleSceneArray, AceLoadHintLowKey: fault == IndoorFaults.AceHintKey);
        if (fault == IndoorFaults.StaleSceneArray && array.Count > 64)
        {
            array.Reset(); // bound the stale growth; still far from a per-call reset
        }
        else if (fault != IndoorFaults.StaleSceneArray)
        {
            array.Reset();
        }

        Sphere[] s = [.. spheres];
        bool customPick = fault == IndoorFaults.OutdoorWins || fault == IndoorFaults.NoReframe;
        bool loadCells = fault == IndoorFaults.NoVisibilityFilter;
        var options = new CellQueryOptions(PickPolicy.Retail, !customPick, loadCells || customPick, fidelity);
        var result = SceneQuery.FindCellList(array, built, cell, s, current, options);
        var containing = result.Containing;
        if (customPick)
        {
            bool visible = cell.IsIndoorByLowWord ? built.GetEnvCell(cell) is not null : cell.IsLand && built.IsLoaded(cell.Landblock);
            containing = visible && s.Length > 0 ? PickFaulty(built, cell, s[0].Center) : CellId.None;
            if (cell.IsIndoorByLowWord && visible && s.Length > 0)
            {
                SceneQuery.FilterVisible(array, built, cell);
            }
        }

        if (fault == IndoorFaults.KeepCurrentOnMiss && containing.IsNone)
        {
            containing = current;
        }

        return new FindCellResult(array.ToIdArray(), containing);
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
