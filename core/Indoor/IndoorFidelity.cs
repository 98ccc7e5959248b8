namespace AcPhys.Core;

/// <summary>
/// Where ACE and retail differ on the indoor paths (facts §7 #6–#14, #9 included), plus one non-retail fix a port may choose.
/// Retail by default.
/// </summary>
/// <param name="AceKeepsStaleCells">#6: find_cell_list does not clear the array (entries of earlier calls survive).</param>
/// <param name="AceEarlyReturn">#7: an interior pick returns at once, skipping the visibility filter.</param>
/// <param name="AceFilterOutsideGuard">#8: the filter runs even with no spheres or no starting cell (ACE would throw on a null cell; modelled as "keep only the position").</param>
/// <param name="AceNeighbourViaVisibleCells">#10: a portal's neighbour is looked up in this cell's VisibleCells, not among all loaded cells.</param>
/// <param name="AceLoadHintLowKey">#11: a load hint is keyed by the bare 16-bit OtherCellId.</param>
/// <param name="AceOutsideByCellId">#12: an exit portal is OtherCellId == 0xFFFF instead of retail's flag 4.</param>
/// <param name="AceNoPortalGuard">#13: point_in_cell answers for a cell without portals (retail answers false).</param>
/// <param name="DropUnloadedLandCells">#2: land cells of unloaded blocks are skipped instead of added as load hints.</param>
/// <param name="AceTransitionFilters">#9: a movement transition runs the visibility filter as static placement does (a fresh ACE
/// CellArray has LoadCells false; retail's CTransition::init sets do_not_load_cells = 0, so retail does not filter).</param>
/// <param name="ReframeTransit">Not retail: transit and building tests subtract GetBlockOffset(position, cell) from sphere centres, so a building owned by a neighbouring block is entered at once (facts §6.11 says retail does not).</param>
public readonly record struct IndoorFidelity(
    bool AceKeepsStaleCells = false,
    bool AceEarlyReturn = false,
    bool AceFilterOutsideGuard = false,
    bool AceNeighbourViaVisibleCells = false,
    bool AceLoadHintLowKey = false,
    bool AceOutsideByCellId = false,
    bool AceNoPortalGuard = false,
    bool DropUnloadedLandCells = false,
    bool ReframeTransit = false,
    bool AceTransitionFilters = false)
{
    /// <summary>
    /// Gets a value indicating whether the parts building entry pairs the box side as ACE does (facts §7 #14, §5.3): ACE
    /// accepts a box wholly on the Positive side when PortalSide (retail: Negative, the cell's own side). A property, not
    /// a positional parameter, so the shipped constructor and Deconstruct keep their shape.
    /// </summary>
    public bool AceBoxSidePairing { get; init; }

    /// <summary>Gets retail behaviour.</summary>
    public static IndoorFidelity Retail => default;

    /// <summary>Gets ACE's behaviour on every documented difference.</summary>
    public static IndoorFidelity Ace => new(true, true, true, true, true, true, true, true, AceTransitionFilters: true) { AceBoxSidePairing = true };

    /// <summary>Gets the outdoor part of this fidelity.</summary>
    public OutdoorFidelity Outdoor => new(DropUnloadedLandCells);
}
