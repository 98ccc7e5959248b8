namespace AcPhys.Core;

/// <summary>How one find_cell_list call is made: the pick, the visibility filter, and the fidelity.</summary>
/// <param name="Policy">Retail pick or current-cell-first.</param>
/// <param name="Pick">Whether the containing-cell pick runs (retail's optional out-pointer; ACE's non-null currCell, facts §4 step 4b).</param>
/// <param name="LoadCells">True disables the indoor VisibleCells filter. Set by each caller (facts §6.14): retail transitions
/// and dynamic objects true (do_not_load_cells = 0), static placement false.</param>
/// <param name="Fidelity">Retail or ACE on the documented differences.</param>
public readonly record struct CellQueryOptions(PickPolicy Policy, bool Pick, bool LoadCells, IndoorFidelity Fidelity = default)
{
    /// <summary>Gets a retail movement query: pick on, no filter (CTransition::init, facts §4 step 5).</summary>
    public static CellQueryOptions RetailTransition => new(PickPolicy.Retail, true, true);

    /// <summary>Gets a retail static placement query: pick on, filter on (calc_cross_cells_static).</summary>
    public static CellQueryOptions RetailStatic => new(PickPolicy.Retail, true, false);
}

/// <summary>What find_cell_list reports besides the array.</summary>
/// <param name="Containing">The containing cell, or <see cref="CellId.None"/> (no pick, or no candidate contains sphere 0's centre).</param>
/// <param name="HitsInteriorCell">The path flag: an indoor seed, a building entry or an interior pick happened.</param>
public readonly record struct CellQueryResult(CellId Containing, bool HitsInteriorCell);
