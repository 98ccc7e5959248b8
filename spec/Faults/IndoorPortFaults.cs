namespace AcPhys.Spec.Faults;

/// <summary>
/// Planted faults of a port's indoor transit (issue #15): each is one defect a port's maintainers plausibly write in
/// find_cell_list, portal transit, building entry or the cell volumes, run by <see cref="FaultySceneQuery"/>.
/// </summary>
internal static class IndoorPortFaults
{
    /// <summary>Neighbour tested in the walked cell's frame.</summary>
    public static readonly PlantedFault NeighbourWrongFrame = new(
        "neighbour-wrong-frame",
        "a portal neighbour's volume is tested with the sphere mapped into the walked cell's frame instead of the neighbour's",
        "facts §5.1, §5.8: the exit and load-hint tests use this cell's frame, the neighbour test the neighbour's; a port hoists one GlobalToLocal out of the portal loop. Invisible while every cell of a building shares one frame.",
        ["PORTAL-TRANSIT", "ENTER-EXIT", "NEVER-NULL", "SCENE-SOUNDNESS", "NEIGHBOURS-COMPLETE", "ENV-CANDIDATE-JUSTIFIED", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Building entry through the first building portal only.</summary>
    public static readonly PlantedFault BuildingFirstPortalOnly = new(
        "building-first-portal-only",
        "building entry looks only at the building's first building portal (a loader keeps one door per building)",
        "facts §5.3: find_building_transit_cells tries every BldPortal in list order; a port that models \"the door\" of a building never enters the room behind a back door from outside.",
        ["PORTAL-TRANSIT", "BUILDING-ENTRY-COMPLETE", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Building entry stops at the first room.</summary>
    public static readonly PlantedFault BuildingStopFirstRoom = new(
        "building-stop-first-room",
        "building entry breaks out of the building-portal loop at the first room it enters",
        "facts §5.3: retail stops at the first hit of the sphere loop inside check_building_transit, not of the portal loop; a port moved the break one loop out. Equivalent while the rooms behind two doors are portal-linked (the closure adds the second, in the same order); seen where two doors' rooms meet at a sealed wall (a duplex or terrace) and a facade walk's sphere reaches both.",
        ["BUILDING-ENTRY-COMPLETE", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Transit closure over a snapshot.</summary>
    public static readonly PlantedFault SnapshotClosure = new(
        "snapshot-closure",
        "the transit closure walks a snapshot of the candidate array (count read once) instead of the growing array",
        "facts §4 step 4a: the count is re-read each time, so cells added during the walk are walked too; the seed pseudocode's comment \"snapshot — cells may be added during iteration\" invites reading it once, and a room entered from land is never walked (its exits and neighbours are lost).",
        ["PORTAL-TRANSIT", "ENTER-EXIT", "NEVER-NULL", "NEIGHBOURS-COMPLETE", "LAND-VIA-EXIT", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Exit straddle test without a lower bound.</summary>
    public static readonly PlantedFault ExitStraddleOneSided = new(
        "exit-straddle-one-sided",
        "the exit-portal straddle test is only d < r + EPS (no lower bound), so land cells are pulled in deep inside a room",
        "facts §5.1, §6.9: an exit triggers only while a sphere straddles the plane, −R < d < R; a port wrote the one bound it thought of, so every sphere on the negative side adds the outdoor cells.",
        ["LAND-VIA-EXIT", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Invalid building portal entered.</summary>
    public static readonly PlantedFault InvalidBldPortalEntered = new(
        "invalid-bld-portal-entered",
        "a building portal whose OtherPortalId is 0xFFFF (no portal) is entered anyway",
        "facts §5.3: check_building_transit returns at once for portalId 0xFFFF (retail stores it sign-extended and tests ≥ 0); a port that reads it as unsigned and never uses the id drops the test.",
        ["ENV-CANDIDATE-JUSTIFIED", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Loaded neighbour added by the plane test.</summary>
    public static readonly PlantedFault NeighbourByPlane = new(
        "neighbour-by-plane",
        "a loaded neighbour is added when a sphere reaches its portal's plane (the load-hint test reused), its volume never tested",
        "facts §5.1: a loaded neighbour needs sphere_intersects_cell (unpadded radius, the BSP's 0.01), only an unresolvable one the plane test (R = r + EPS); a port merged the two branches.",
        ["SCENE-SOUNDNESS", "NEIGHBOURS-COMPLETE", "ENV-CANDIDATE-JUSTIFIED", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Negative BSP children walked.</summary>
    public static readonly PlantedFault WalksNegativeChildren = new(
        "walks-negative-children",
        "the cell queries walk the whole BSP (every piece of a multi-piece cell), not only the positive chain",
        "facts §5.7, §6.16: all three cell queries follow the positive-child chain and ignore negative children, so a multi-piece cell answers for its first piece; a port wrote the textbook BSP traversal. (Replaces the brief's first-piece-only, which is exactly retail.) Seen where a sphere reaches an L room's second piece but not its first: a facade walk past a door room's notch (building entry lets the room in).",
        ["ENV-CANDIDATE-JUSTIFIED", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Interior pick keeps the last env hit.</summary>
    public static readonly PlantedFault PickLastEnv = new(
        "pick-last-env",
        "the interior pick keeps the last env cell containing sphere 0's centre instead of the first",
        "facts §4 step 4b, §6.6: the first env hit wins (ACE returns at once), the last land hit wins; a port applied the outdoor last-wins rule to both. Visible where cells overlap: a shared wall within EPS, a stairwell.",
        ["PORTAL-TRANSIT", "PICK-FIRST-ENV", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Pick by the last sphere.</summary>
    public static readonly PlantedFault PickLastSphere = new(
        "pick-last-sphere",
        "the containing pick tests the last sphere's centre instead of sphere 0's",
        "facts §4 step 4b, §6.8: only sphere 0 decides the containing cell; a port's loop variable leaked out of the sphere loop.",
        ["PORTAL-TRANSIT"]);

    /// <summary>Filter drops load hints.</summary>
    public static readonly PlantedFault FilterDropsHints = new(
        "filter-drops-hints",
        "the visibility filter applies its keep test to load hints too, so every hint is removed",
        "facts §4 step 5: the filter skips null (load-hint) entries and ACE never removes them; a port that stores hints as entries with no cell runs the same visible-and-loaded test on them.",
        ["PORTAL-TRANSIT", "FIND-CELL-CONFORMANCE"]);

    /// <summary>HitsInteriorCell not set by building entry.</summary>
    public static readonly PlantedFault HitsInteriorUnset = new(
        "hits-interior-unset",
        "building entry does not set HitsInteriorCell (only an indoor seed or an interior pick does)",
        "facts §4 outputs, §5.3: check_building_transit sets path.HitsInteriorCell on entry; a port that reads the flag as \"the body is indoors\" sets it only from the pick, so building collision keeps its centre-solid test while a body straddles the door.",
        ["HITS-INTERIOR", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Close treated as outside.</summary>
    public static readonly PlantedFault CloseIsOutside = new(
        "close-is-outside",
        "point_inside_cell treats Close (|d| ≤ EPS) as outside",
        "facts §5.7: Behind → false, Front and Close move on, so inside ⇔ d ≥ −EPS for every plane; a port tested d > EPS, and a centre on a wall or a door line is in no cell.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Sphere test without the 0.01 padding.</summary>
    public static readonly PlantedFault SphereTestUnpadded = new(
        "sphere-test-unpadded",
        "sphere_intersects_cell without the +0.01 radius padding",
        "facts §5.7, §6.10: R = r + 0.01 inside sphere_intersects_cell_bsp (not EPS); a port kept \"radius not padded\" of the callers and dropped the BSP's own padding, so a room is entered 1 cm late.",
        ["NEIGHBOURS-COMPLETE", "BUILDING-ENTRY-COMPLETE", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Transit and building entry by sphere 0 only.</summary>
    public static readonly PlantedFault TransitSphere0Only = new(
        "transit-sphere0-only",
        "env transit and building entry test only sphere 0",
        "facts §6.8: only sphere 0 decides the pick, but all spheres decide membership; a port applied the pick's rule to the transit loops, so a two-sphere body's head enters a room its feet have not reached without the room.",
        ["NEIGHBOURS-COMPLETE", "BUILDING-ENTRY-COMPLETE", "LAND-VIA-EXIT", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Pick before the transit closure.</summary>
    public static readonly PlantedFault PickBeforeTransit = new(
        "pick-before-transit",
        "the containing pick runs on the seeded array, before the transit closure",
        "facts §4 step 4: the pick (4b) runs after the closure (4a); a port computed \"the cell we start in\" right after seeding, so a room entered from land or a neighbour reached through a portal is never picked (absorbing states).",
        ["INTERIOR-WINS", "PORTAL-TRANSIT", "NEVER-NULL", "PICK-FIRST-ENV", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Load hint by straddle.</summary>
    public static readonly PlantedFault HintStraddleOnly = new(
        "hint-straddle-only",
        "the load-hint test is the exit portal's straddle test (|d| < r + EPS, no PortalSide)",
        "facts §5.1, §5.4: an unresolvable neighbour is hinted when a sphere reaches its side (PortalSide and d > −R, or !PortalSide and d < R), also when wholly past the plane; a port copied the exit branch.",
        ["PORTAL-TRANSIT", "FIND-CELL-CONFORMANCE"]);

    /// <summary>ACE's early return while declaring retail.</summary>
    public static readonly PlantedFault EarlyReturnUndeclared = new(
        "early-return-undeclared",
        "an interior pick returns at once and skips the visibility filter (ACE's OC:381) while the port declares retail",
        "facts §4 step 5, §7 #7: retail's loop breaks and falls through to the filter; a port translated ACE's \"break?\" return, so land cells added by a straddled exit survive a static query from a room.",
        ["VISIBILITY", "FIND-CELL-CONFORMANCE"]);

    /// <summary>The portal-less guard applied in transit instead of point_in_cell.</summary>
    public static readonly PlantedFault PortalGuardInTransit = new(
        "portal-guard-in-transit",
        "a cell without portals is never made a candidate (building entry and the neighbour test skip it) instead of only being refused by point_in_cell",
        "facts §5.5, §7 #13: retail's point_in_cell returns false for a cell with no portals, but building entry (§5.3) and the neighbour test (§5.1) still add it, set HitsInteriorCell and keep it as a candidate; a port that read the guard as \"such a cell is unreachable\" drops it from the array. Seen only where a sealed closet (a cell with no cell portals, entered by its own building portal) is reached.",
        ["BUILDING-ENTRY-COMPLETE", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Gets every fault of this list.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } =
    [
        NeighbourWrongFrame, BuildingFirstPortalOnly, BuildingStopFirstRoom, SnapshotClosure, ExitStraddleOneSided, InvalidBldPortalEntered,
        NeighbourByPlane, WalksNegativeChildren, PickLastEnv, PickLastSphere, FilterDropsHints, HitsInteriorUnset, CloseIsOutside,
        SphereTestUnpadded, TransitSphere0Only, PickBeforeTransit, HintStraddleOnly, EarlyReturnUndeclared, PortalGuardInTransit,
        .. FilterOrderFaults.All,
        .. CornerFaults.All,
        .. InteriorFaults.All,
    ];

    /// <summary>Returns the code defect a fault plants in <see cref="FaultySceneQuery"/> (none for a volume or data fault).</summary>
    /// <param name="fault">A fault of this list.</param>
    /// <returns>The defect.</returns>
    internal static IndoorDefect DefectOf(PlantedFault fault) => fault.Id switch
    {
        "neighbour-wrong-frame" => IndoorDefect.NeighbourWrongFrame,
        "building-stop-first-room" => IndoorDefect.BuildingStopFirstRoom,
        "snapshot-closure" => IndoorDefect.SnapshotClosure,
        "exit-straddle-one-sided" => IndoorDefect.ExitStraddleOneSided,
        "invalid-bld-portal-entered" => IndoorDefect.InvalidBldPortalEntered,
        "neighbour-by-plane" => IndoorDefect.NeighbourByPlane,
        "pick-last-env" => IndoorDefect.PickLastEnv,
        "pick-last-sphere" => IndoorDefect.PickLastSphere,
        "filter-drops-hints" => IndoorDefect.FilterDropsHints,
        "hits-interior-unset" => IndoorDefect.HitsInteriorUnset,
        "transit-sphere0-only" => IndoorDefect.TransitSphere0Only,
        "pick-before-transit" => IndoorDefect.PickBeforeTransit,
        "hint-straddle-only" => IndoorDefect.HintStraddleOnly,
        "early-return-undeclared" => IndoorDefect.EarlyReturnUndeclared,
        "portal-guard-in-transit" => IndoorDefect.PortalGuardInTransit,
        _ => FilterOrderFaults.DefectOf(fault) is var filter && filter != IndoorDefect.None ? filter : CornerFaults.DefectOf(fault) is var corner && corner != IndoorDefect.None ? corner : InteriorFaults.DefectOf(fault),
    };

    /// <summary>Returns the volume decorator a fault plants, or null.</summary>
    /// <param name="fault">A fault of this list.</param>
    /// <returns>The decorator (retail volume, the cell's pieces → faulty volume), or null.</returns>
    internal static Func<Core.ICellVolume, IReadOnlyList<Core.ConvexPiece>, Core.ICellVolume>? VolumeOf(PlantedFault fault) => fault.Id switch
    {
        "close-is-outside" => (v, pieces) => new CloseIsOutsideVolume(v, pieces[0]),
        "sphere-test-unpadded" => (v, pieces) => new ChainSphereVolume(v, pieces[0], ChainSphereVolume.Unpadded),
        "walks-negative-children" => (v, pieces) => new PieceUnionVolume(v, pieces),
        _ => CornerFaults.VolumeOf(fault) ?? InteriorFaults.VolumeOf(fault),
    };
}
