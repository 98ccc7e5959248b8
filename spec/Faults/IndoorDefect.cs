namespace AcPhys.Spec.Faults;

/// <summary>The one defect a <see cref="FaultySceneQuery"/> carries (none: it answers as the reference core does).</summary>
internal enum IndoorDefect
{
    /// <summary>No defect.</summary>
    None,

    /// <summary>A portal neighbour's volume is tested with the sphere in the walked cell's frame.</summary>
    NeighbourWrongFrame,

    /// <summary>Building entry stops at the first room it enters.</summary>
    BuildingStopFirstRoom,

    /// <summary>The transit closure walks a snapshot of the array (count read once).</summary>
    SnapshotClosure,

    /// <summary>The exit-portal straddle test has no lower bound (only d &lt; r + EPS).</summary>
    ExitStraddleOneSided,

    /// <summary>A building portal with OtherPortalId 0xFFFF is entered anyway.</summary>
    InvalidBldPortalEntered,

    /// <summary>A loaded neighbour is added by the load-hint plane test, its volume never tested.</summary>
    NeighbourByPlane,

    /// <summary>The interior pick keeps the last env cell containing the centre.</summary>
    PickLastEnv,

    /// <summary>The pick uses the last sphere's centre.</summary>
    PickLastSphere,

    /// <summary>The visibility filter also removes load hints.</summary>
    FilterDropsHints,

    /// <summary>Building entry does not set HitsInteriorCell.</summary>
    HitsInteriorUnset,

    /// <summary>Env transit and building entry test sphere 0 only.</summary>
    TransitSphere0Only,

    /// <summary>The pick runs on the seeded array, before the transit closure.</summary>
    PickBeforeTransit,

    /// <summary>The load-hint test is the exit portal's straddle test (no PortalSide).</summary>
    HintStraddleOnly,

    /// <summary>ACE's early return after an interior pick (the filter skipped) while declaring retail.</summary>
    EarlyReturnUndeclared,

    /// <summary>A cell without portals is never added by building entry or a portal neighbour test (the point_in_cell guard moved into transit).</summary>
    PortalGuardInTransit,

    /// <summary>The visibility filter keeps the survivors in insertion order (<see cref="FilterOrderFaults"/>).</summary>
    FilterStableOrder,

    /// <summary>The visibility filter never tests the entry it swapped into a hole.</summary>
    FilterSkipsSwappedIn,

    /// <summary>The visibility filter walks from the last entry to the first.</summary>
    FilterFromEnd,

    /// <summary>The visibility filter walks the live array and re-tests the swapped-in entry at once.</summary>
    FilterLiveRecheck,

    /// <summary>Issue 27: the neighbour sphere test pads the radius by EPS (before the BSP's own 0.01).</summary>
    NeighbourPaddedEps,

    /// <summary>Issue 27: the neighbour sphere test pads the radius by 0.01 (the BSP's padding applied twice).</summary>
    NeighbourPaddedBsp,

    /// <summary>Issue 27: building entry pads the radius by EPS.</summary>
    BuildingEntryPadded,

    /// <summary>Issue 27: the exit and load-hint plane tests use R = r (no EPS).</summary>
    PortalPlaneUnpadded,

    /// <summary>Issue 27: the exit and load-hint plane tests use R = r − EPS (the padding's sign flipped).</summary>
    PortalPlanePadNegated,

    /// <summary>Issue 27: the exit and load-hint plane tests pad by the BSP's 0.01 instead of EPS.</summary>
    PortalPlaneBspPad,

    /// <summary>Issue 27: the transit closure stops at the first load hint.</summary>
    ClosureBreaksAtHint,

    /// <summary>Issue 27: the transit closure skips the entry after a load hint too.</summary>
    ClosureSkipsAfterHint,

    /// <summary>Issue 27: the transit closure's bound is the count minus the hints seen so far.</summary>
    ClosureBoundMinusHints,

    /// <summary>Issue 41: the exit straddle is inclusive (−R ≤ d ≤ R).</summary>
    ExitStraddleInclusive,

    /// <summary>Issue 41: the load-hint side test is inclusive (PortalSide d ≥ −R, else d ≤ R).</summary>
    HintBoundInclusive,

    /// <summary>Issue 41: building entry asks only the building of the land cell under sphere 0's centre.</summary>
    BuildingCentreCellOnly,

    /// <summary>Issue 41: building entry is asked only when the query starts outdoors.</summary>
    BuildingEntryOutdoorsOnly,

    /// <summary>Issue 41: from indoors, building entry asks only the building whose rooms hold the position's cell.</summary>
    BuildingOwnBuildingIndoors,
}
