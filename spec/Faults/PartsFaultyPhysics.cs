using System.Runtime.CompilerServices;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>The reference with one defect of its parts variant indoors (<see cref="PartsIndoorFaults"/>); every other answer is the reference's.</summary>
/// <param name="fault">The fault, or null for the model with no defect.</param>
internal sealed class PartsFaultyPhysics(PlantedFault? fault) : ForwardingPhysics(ReferenceAdapter.Instance)
{
    private readonly ConditionalWeakTable<Scene, CellScene> built = [];
    private readonly CellArray array = new();

    /// <inheritdoc/>
    public override string Name => "reference+" + (fault?.Id ?? "parts-model");

    // A walk goes query by query through this model (ICellPhysics.FindCellWalk's default), not to the reference whole.
    /// <inheritdoc/>
    public override IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) => WalkThread.AskEach(this, walk);

    // A parts walk too goes query by query through this model (ICellPhysics.FindCellPartsWalk's default).
    /// <inheritdoc/>
    public override IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) =>
        [.. queries.Select(q => FindCellParts(scene, q, loadCells))];

    /// <inheritdoc/>
    public override FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells)
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
