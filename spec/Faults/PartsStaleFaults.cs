using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// Planted faults of a port that declares ace-keeps-stale-cells (facts §7 #6) for its parts list (issue 53): a port
/// written after ACE whose sphere find_cell_list keeps the previous call's cells, as declared, but whose parts
/// find_bbox_cell_list clears its list each query — retail's truncation written out of habit (§4 step 1: "Clear it").
/// </summary>
internal static class PartsStaleFaults
{
    /// <summary>The parts list cleared each query under a declared ace-keeps-stale-cells.</summary>
    public static readonly PlantedFault Cleared = new(
        "parts-stale-cleared",
        "a port declaring ace-keeps-stale-cells keeps the sphere list's stale cells across a walk but clears the parts list at each parts query",
        "facts §3.5, §4 step 1, §7 #6: ACE's find_bbox_cell_list resets only the AddedOutside latch, never the cells, so under the declared deviation each parts answer keeps the previous one's cells; a port that clears the parts list (as retail truncates) answers as retail in a mode whose reference keeps them.",
        ["PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Gets every fault of this family.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [Cleared];

    /// <summary>Returns an adapter carrying a fault of this family, or null for another fault.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The adapter, or null.</returns>
    public static ICellPhysics? Create(PlantedFault fault) =>
        fault == Cleared ? new ClearedParts(new ReferenceAdapter(PickPolicy.Retail) { Indoor = IndoorFidelity.Retail with { AceKeepsStaleCells = true } }) : null;

    // The stale reference, its parts walk asked query by query: each parts query starts from an empty list.
    private sealed class ClearedParts(ICellPhysics inner) : ForwardingPhysics(inner)
    {
        public override string Name => Inner.Name + "+" + Cleared.Id;

        public override IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells) =>
            [.. queries.Select(q => Inner.FindCellParts(scene, q, loadCells))];
    }
}
