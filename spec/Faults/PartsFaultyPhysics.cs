using System.Numerics;
using System.Runtime.CompilerServices;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>The reference with one defect of its parts variant indoors (<see cref="PartsIndoorFaults"/>); every other answer is the reference's.</summary>
/// <param name="fault">The fault, or null for the model with no defect.</param>
internal sealed class PartsFaultyPhysics(PlantedFault? fault) : ICellPhysics
{
    private readonly ConditionalWeakTable<Scene, CellScene> built = [];
    private readonly CellArray array = new();
    private readonly ReferenceAdapter reference = ReferenceAdapter.Instance;

    public string Name => "reference+" + (fault?.Id ?? "parts-model");

    public Op Ops => Op.All;

    public PickPolicy Pick => PickPolicy.Retail;

    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => reference.BlockIdToLcoord(id, out lcoord);

    public bool GidToLcoord(CellId id, out Lcoord lcoord) => reference.GidToLcoord(id, out lcoord);

    public CellId LcoordToGid(int x, int y) => reference.LcoordToGid(x, y);

    public bool InboundValidCellId(CellId id) => reference.InboundValidCellId(id);

    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => reference.GetOutsideLcoord(id, x, y, out lcoord);

    public AdjustResult AdjustToOutside(CellId id, float x, float y) => reference.AdjustToOutside(id, x, y);

    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => reference.OutsideCells(cell, spheres);

    public IReadOnlyList<CellId> OutsideCells(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres) => reference.OutsideCells(cell, origin, spheres);

    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => reference.FindCell(cell, spheres, current);

    public FindCellResult FindCell(CellId cell, Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) => reference.FindCell(cell, origin, spheres, current);

    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => reference.OutsideCellsParts(parts);

    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => reference.FindCell(scene, cell, spheres, current);

    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) => reference.FindCell(scene, cell, spheres, current, loadCells);

    public FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells)
    {
        bool hits = FaultyPartsQuery.FindCellList(array, built.GetValue(scene, s => SceneBuild.Build(s)), [.. parts], loadCells, fault);
        var flags = new bool[array.Count];
        for (int i = 0; i < flags.Length; i++)
        {
            flags[i] = array[i].Loaded;
        }

        return new FindCellResult(array.ToIdArray(), CellId.None) { HitsInteriorCell = hits, Loaded = flags };
    }
}
