using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>The reference answering the parts variant in a scene for parts misread by a <see cref="PartsFrameFaults"/> fault; every other answer is the reference's.</summary>
/// <param name="fault">The fault.</param>
internal sealed class PartsMisreadPhysics(PlantedFault fault) : ForwardingPhysics(ReferenceAdapter.Instance)
{
    /// <inheritdoc/>
    public override string Name => "reference+" + fault.Id;

    /// <inheritdoc/>
    public override FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) =>
        Inner.FindCellParts(scene, PartsMisread.Read(parts, fault), loadCells);

    /// <inheritdoc/>
    public override IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) =>
        Inner.FindCellPartsWalk(scene, [.. queries.Select(q => (IReadOnlyList<Part>)PartsMisread.Read(q, fault))], loadCells);
}
