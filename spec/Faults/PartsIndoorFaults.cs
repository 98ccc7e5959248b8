using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// Planted faults of a port's parts variant indoors (issue 41): each is one defect a port plausibly writes in its
/// bounding-box cell list, run by <see cref="FaultyPartsQuery"/>; every other answer is the reference's.
/// </summary>
internal static class PartsIndoorFaults
{
    /// <summary>Only the first part probes portals.</summary>
    public static readonly PlantedFault FirstPartOnly = new(
        "parts-first-part-only",
        "only the first part probes an env cell's portals and the building doors (the anchor stands for the object)",
        "facts §5.2, §5.3: the transit loops run over every part with a sphere; a port carried \"the first part is the anchor\" of the outdoor variant (§3.4) into the indoor loops, so a limb through a door is never seen.",
        ["PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Boxes not transformed into the cell's frame.</summary>
    public static readonly PlantedFault BoxUntransformed = new(
        "parts-box-untransformed",
        "a part's box is tested against a cell's portals and volume in the part's block frame, never transformed into the cell's frame",
        "facts §5.2, §5.8: the box is BBox.LocalToLocal'd into this cell's frame (and the neighbour's); a port took the part's box in its position's frame, which is right only for a cell whose frame is the block's.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Building entry by the anchor part only.</summary>
    public static readonly PlantedFault BuildingAnchorOnly = new(
        "parts-building-anchor-only",
        "the parts building check (check_building_transit) asks the anchor part only",
        "facts §5.3: check_building_transit loops over the parts; a port that enters a building \"where the object is\" asks its anchor, so an object reaching a door with another part stays outside.",
        ["PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Parts order lost: part-major transit loops.</summary>
    public static readonly PlantedFault OrderLost = new(
        "parts-order-lost",
        "the parts transit loops nest part-major (each part probes every portal in turn) instead of portal-major, so the order of the neighbours added is the parts' order, not the portals'",
        "facts §5.2: for each portal, for each part — the first part through a portal decides it and the portal order decides the list; a port that iterates the object's parts outermost (as its outdoor code does) lists the neighbours another part reaches first.",
        ["PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>ACE's box-side pairing at a building door while declaring retail: a documented deviation served undeclared.</summary>
    public static readonly PlantedFault AceBoxSideUndeclared = new(
        "ace-box-side-undeclared",
        "the parts building entry pairs the box side as ACE does (a box wholly on the door's outer side enters, one wholly on the room's side does not) while the port declares retail",
        "facts §5.3, §7 #14: retail's parts check_building_transit accepts a box that is Crossing or wholly on portal_side's side (Negative when PortalSide); ACE pairs Positive with PortalSide. A port translated ACE's pairing and declares retail; declaring ace-box-side-pairing (or ace) makes it intended. Seen only where a part's sphere reaches a building door while its box lies wholly on one side of the door's plane.",
        ["PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Gets every fault of the parts variant indoors.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [FirstPartOnly, BoxUntransformed, BuildingAnchorOnly, OrderLost, AceBoxSideUndeclared];

    /// <summary>Returns an adapter carrying a fault of the parts variant indoors (this family's or <see cref="PartsShapeFaults"/>'), or null for another fault.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The adapter, or null.</returns>
    public static ICellPhysics? Create(PlantedFault fault) =>
        fault == AceBoxSideUndeclared ? PortShimFaults.AnnouncingRetail(new ReferenceAdapter(PickPolicy.Retail) { Indoor = IndoorFidelity.Retail with { AceBoxSidePairing = true } })
        : All.Contains(fault) || PartsShapeFaults.All.Contains(fault) ? new PartsFaultyPhysics(fault)
        : null;
}
