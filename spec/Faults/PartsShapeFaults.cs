namespace AcPhys.Spec.Faults;

/// <summary>
/// Planted faults of a port's parts variant that only retail-like part shapes and anchors tell from retail (issue 53):
/// each is one defect as a port would write it, run by <see cref="FaultyPartsQuery"/> (the parts model of
/// <see cref="PartsIndoorFaults"/>); every other answer is the reference's. A box that pokes out of its sphere, a flat or
/// a long box, a sphere across a portal whose box is not, and an anchor the scene lacks reach them
/// (spec/Cases/PartShapes, PartAnchors; the classes of ScenePartsClasses).
/// </summary>
internal static class PartsShapeFaults
{
    /// <summary>The box test before the sphere gate: a crossing box passes whatever the gate says.</summary>
    public static readonly PlantedFault BoxBeforeGate = new(
        "parts-box-before-gate",
        "the parts portal and door checks test the box first and consult the sphere gate only when the box does not cross the plane (a crossing box is let through)",
        "facts §5.2, §5.3: the sphere gate (d against R = r + EPS) decides before the box; a port that reasons \"the box is the finer test\" and short-cuts on a crossing box lets a box that pokes out of its sphere through a portal whose gate shuts it out.",
        ["PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>A two-sided sphere gate.</summary>
    public static readonly PlantedFault GateTwoSided = new(
        "parts-gate-two-sided",
        "the parts sphere gate skips a part whose centre is farther than r + EPS from the plane on either side (|d| > R), not only on the side PortalSide shuts",
        "facts §5.2, §5.3: the gate is one-sided — transit skips d < −R when PortalSide, else d > R; entry the mirror — so a part whose centre is already past the plane still has its box tested; a port writing the sphere variant's straddle test (§5.1 outdoor portal) drops a box reaching back across.",
        ["PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>The neighbour tested by the part's sphere, not its box.</summary>
    public static readonly PlantedFault NeighbourBySphere = new(
        "parts-neighbour-by-sphere",
        "the parts transit adds a portal's neighbour when the part's sphere (in the neighbour's frame) intersects it, not the part's box",
        "facts §5.2: after the gate and the box side, the neighbour is added when box_intersects_cell(part bbox in the neighbour's frame); a port that reused the sphere variant's sphere_intersects_cell (§5.1) answers differently for a flat or long box, or one poking out of its sphere.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>The box-side test of the transit skipped.</summary>
    public static readonly PlantedFault BoxSideSkipped = new(
        "parts-box-side-skipped",
        "the parts transit skips the box-side test (Plane.intersect_box): a part whose sphere passes the gate goes on to the portal's neighbour, exit or load hint even when its box lies wholly on the cell's own side",
        "facts §5.2, §5.7: a part passing the sphere gate is still turned back when its box lies wholly on the cell's side of the portal (Positive and !PortalSide, or Negative and PortalSide); a port that deems the gate enough adds the outdoor cells or a load hint for a sphere across a portal whose box is not.",
        ["PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>An anchor the scene lacks answers an empty list.</summary>
    public static readonly PlantedFault MissingAnchorEmpty = new(
        "parts-missing-anchor-empty",
        "a parts query whose anchor is indoor by its low word but names no loaded env cell (a missing cell, or a landblock id) answers an empty list with HitsInteriorCell false",
        "facts §1.1, §4 steps 2–3: an anchor indoor by its low word (0xFFFF included) sets HitsInteriorCell and is added with its load flag even when the scene lacks it (a load hint); a port that bails out on a cell it cannot find answers nothing.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Gets every fault of this family.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [BoxBeforeGate, GateTwoSided, NeighbourBySphere, BoxSideSkipped, MissingAnchorEmpty];
}
