using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// Issue 27: planted faults of the two indoor corners the generators now reach — near-touch padding (facts §6.10:
/// +EPS for portal planes, +0.01 inside the BSP sphere test, none for the neighbour and building callers) and load
/// hints early in the transit closure (facts §4 step 4a). Run by <see cref="FaultySceneQuery"/> (code defects) or a
/// cell-volume decorator (<see cref="NearTouchSphereVolume"/>). Two variants were written and dropped: an inclusive exit
/// straddle (−R ≤ d ≤ R) and a strict BSP bound (Outside iff d &lt; −R) differ from retail only at the exact float32 tie,
/// which FIND-CELL-CONFORMANCE excuses in scenes by design (a probe 8 ulps away explains it; docs/conformance.md).
/// </summary>
internal static class CornerFaults
{
    /// <summary>Neighbour test padded by EPS.</summary>
    public static readonly PlantedFault NeighbourPaddedEps = new(
        "neighbour-padded-eps",
        "the portal-neighbour sphere test pads the radius by EPS before sphere_intersects_cell",
        "facts §5.1, §6.10: the neighbour test passes the radius unpadded (the BSP adds its 0.01); a port padded every portal test by EPS as the plane tests are, so a neighbour is added at gaps r + 0.01 … r + 0.0102.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Neighbour test padded by 0.01.</summary>
    public static readonly PlantedFault NeighbourPaddedBsp = new(
        "neighbour-padded-bsp",
        "the portal-neighbour sphere test pads the radius by 0.01 before sphere_intersects_cell (the BSP's padding twice)",
        "facts §5.7, §6.10: R = r + 0.01 is the BSP's own padding; a port copied it into the caller as well, so a neighbour is added up to 2 cm away.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Building entry padded by EPS.</summary>
    public static readonly PlantedFault BuildingEntryPadded = new(
        "building-entry-padded",
        "check_building_transit pads the radius by EPS before sphere_intersects_cell",
        "facts §5.3, §6.10: the spheres variant of check_building_transit passes the radius unpadded (the parts variant pads its plane test by EPS); a port shared one padded helper, so a room is entered at gaps r + 0.01 … r + 0.0102.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Portal plane tests without EPS.</summary>
    public static readonly PlantedFault PortalPlaneUnpadded = new(
        "portal-plane-unpadded",
        "the exit-portal and load-hint plane tests use R = r (no EPS)",
        "facts §5.1, §6.10: the plane tests pad by EPS (EC:167, EC:263, EC:323, EC:357); a port read \"radius not padded\" of the neighbour test as true of all, so exits and hints fire EPS late.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Portal plane tests with the padding subtracted.</summary>
    public static readonly PlantedFault PortalPlanePadNegated = new(
        "portal-plane-pad-negated",
        "the exit-portal and load-hint plane tests use R = r − EPS (the padding's sign flipped)",
        "facts §5.1, §6.10: R = r + EPS; a port moved EPS to the other side of the comparison without flipping its sign.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Portal plane tests padded by 0.01.</summary>
    public static readonly PlantedFault PortalPlaneBspPad = new(
        "portal-plane-bsp-pad",
        "the exit-portal and load-hint plane tests pad by 0.01 (the BSP's padding) instead of EPS",
        "facts §1.5, §6.10: two tolerances, EPS for portal planes and 0.01 inside the cell BSP; a port kept one constant, so exits and hints fire 1 cm early.",
        ["FIND-CELL-CONFORMANCE"]);



    /// <summary>BSP sphere test padded by EPS.</summary>
    public static readonly PlantedFault BspPadsEps = new(
        "bsp-pads-eps",
        "sphere_intersects_cell pads the radius by EPS instead of 0.01",
        "facts §1.5, §5.7, §6.10: R = r + 0.01 inside the BSP sphere test, not EPS; a port used the one tolerance it knew, so rooms are entered about 1 cm late.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Closure stops at the first hint.</summary>
    public static readonly PlantedFault ClosureBreaksAtHint = new(
        "closure-breaks-at-hint",
        "the transit closure stops at the first load hint (a null entry read as the end of the array)",
        "facts §4 step 4a: null (load-hint) entries are skipped and the walk goes on; a port whose array is null-terminated, or that breaks instead of continuing, never walks the loaded cells behind a hint. (A port that treats a hint as the end of the array is this fault: it answers the same.)",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Closure skips the entry after a hint.</summary>
    public static readonly PlantedFault ClosureSkipsAfterHint = new(
        "closure-skips-after-hint",
        "the transit closure skips the entry after a load hint as well (an extra index increment on the skip path)",
        "facts §4 step 4a: only the null entry is skipped; a port advanced its index both in the skip branch and in the loop header, so the cell behind a hint is never walked.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Closure bound minus hints.</summary>
    public static readonly PlantedFault ClosureBoundMinusHints = new(
        "closure-bound-minus-hints",
        "the transit closure's loop bound is the count minus the hints seen so far (a \"loaded cells\" count)",
        "facts §4 step 4a: the bound is the array's count, re-read each time; a port counted only loaded cells, so the last entries after a hint are never walked.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Gets every fault of this list.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } =
    [
        NeighbourPaddedEps, NeighbourPaddedBsp, BuildingEntryPadded, PortalPlaneUnpadded, PortalPlanePadNegated, PortalPlaneBspPad,
        BspPadsEps, ClosureBreaksAtHint, ClosureSkipsAfterHint, ClosureBoundMinusHints,
    ];

    /// <summary>Returns the code defect a fault of this list plants (none for another fault or a volume fault).</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The defect.</returns>
    internal static IndoorDefect DefectOf(PlantedFault fault) => fault.Id switch
    {
        "neighbour-padded-eps" => IndoorDefect.NeighbourPaddedEps,
        "neighbour-padded-bsp" => IndoorDefect.NeighbourPaddedBsp,
        "building-entry-padded" => IndoorDefect.BuildingEntryPadded,
        "portal-plane-unpadded" => IndoorDefect.PortalPlaneUnpadded,
        "portal-plane-pad-negated" => IndoorDefect.PortalPlanePadNegated,
        "portal-plane-bsp-pad" => IndoorDefect.PortalPlaneBspPad,
        "closure-breaks-at-hint" => IndoorDefect.ClosureBreaksAtHint,
        "closure-skips-after-hint" => IndoorDefect.ClosureSkipsAfterHint,
        "closure-bound-minus-hints" => IndoorDefect.ClosureBoundMinusHints,
        _ => IndoorDefect.None,
    };

    /// <summary>Returns the volume decorator a fault of this list plants, or null.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The decorator, or null.</returns>
    internal static Func<ICellVolume, IReadOnlyList<ConvexPiece>, ICellVolume>? VolumeOf(PlantedFault fault) => fault.Id switch
    {
        "bsp-pads-eps" => (v, pieces) => new NearTouchSphereVolume(v, pieces[0], LandDefs.Epsilon),
        _ => null,
    };

    /// <summary>The radius the neighbour sphere test passes to sphere_intersects_cell (retail: unpadded, facts §5.1).</summary>
    /// <param name="r">The sphere's radius.</param>
    /// <param name="defect">The defect.</param>
    /// <returns>The radius.</returns>
    internal static float NeighbourRadius(float r, IndoorDefect defect) =>
        defect == IndoorDefect.NeighbourPaddedEps ? r + LandDefs.Epsilon : defect == IndoorDefect.NeighbourPaddedBsp ? r + 0.01f : r;

    /// <summary>The radius building entry passes to sphere_intersects_cell (retail: unpadded, facts §5.3).</summary>
    /// <param name="r">The sphere's radius.</param>
    /// <param name="defect">The defect.</param>
    /// <returns>The radius.</returns>
    internal static float BuildingRadius(float r, IndoorDefect defect) => defect == IndoorDefect.BuildingEntryPadded ? r + LandDefs.Epsilon : r;

    /// <summary>R of the exit and load-hint plane tests (retail: r + EPS, facts §5.1).</summary>
    /// <param name="r">The sphere's radius.</param>
    /// <param name="defect">The defect.</param>
    /// <returns>R.</returns>
    internal static float PlaneRadius(float r, IndoorDefect defect) => defect switch
    {
        IndoorDefect.PortalPlaneUnpadded => r,
        IndoorDefect.PortalPlanePadNegated => r - LandDefs.Epsilon,
        IndoorDefect.PortalPlaneBspPad => r + 0.01f,
        _ => r + LandDefs.Epsilon,
    };
}
