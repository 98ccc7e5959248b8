using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// The single entry point of a membership query: <c>find_cell_list</c> (facts §4). Today it covers open land
/// (land-cell positions, no env cells or buildings); indoor seeding and transit come with scenes.
/// </summary>
public static class CellQuery
{
    /// <summary>
    /// Resets the array, collects the land cells the spheres touch, and picks the containing cell.
    /// Allocation-free once the array's capacity has grown.
    /// </summary>
    /// <param name="array">Reused output array: truncated first (retail, facts §6.13).</param>
    /// <param name="position">A land cell id or block id (normalised by AdjustToOutside, facts §1.1).</param>
    /// <param name="spheres">Sphere centres in <paramref name="position"/>'s block frame; sphere 0 decides the pick.</param>
    /// <param name="current">The current cell, for <see cref="PickPolicy.CurrentFirst"/>; <see cref="CellId.None"/> when none.</param>
    /// <param name="policy">The pick policy.</param>
    /// <param name="landscape">Which blocks are loaded.</param>
    /// <param name="fidelity">Retail or ACE, float32 or the double reference (which also picks in double).</param>
    /// <returns>The containing cell, or <see cref="CellId.None"/>.</returns>
    public static CellId FindCellListOutdoor(
        CellArray array,
        CellId position,
        ReadOnlySpan<Sphere> spheres,
        CellId current,
        PickPolicy policy,
        ILandscape landscape,
        OutdoorFidelity fidelity = default) =>
        FindCellListOutdoor(array, position, Vector3.Zero, spheres, current, policy, landscape, fidelity);

    /// <summary>As <see cref="FindCellListOutdoor(CellArray, CellId, ReadOnlySpan{Sphere}, CellId, PickPolicy, ILandscape, OutdoorFidelity)"/>, with the position's own point.</summary>
    /// <param name="array">Reused output array: truncated first (retail, facts §6.13).</param>
    /// <param name="position">A land cell id or block id.</param>
    /// <param name="origin">The position's point in its block frame: with no spheres retail re-seats it and adds its one cell (facts §3.3 step 3).</param>
    /// <param name="spheres">Sphere centres in <paramref name="position"/>'s block frame; sphere 0 decides the pick.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <param name="policy">The pick policy.</param>
    /// <param name="landscape">Which blocks are loaded.</param>
    /// <param name="fidelity">Retail or ACE, float32 or double.</param>
    /// <returns>The containing cell, or <see cref="CellId.None"/>.</returns>
    public static CellId FindCellListOutdoor(
        CellArray array,
        CellId position,
        Vector3 origin,
        ReadOnlySpan<Sphere> spheres,
        CellId current,
        PickPolicy policy,
        ILandscape landscape,
        OutdoorFidelity fidelity = default)
    {
        array.Reset();
        OutdoorCells.AddAllOutsideCells(array, position, origin, spheres, landscape, fidelity);
        if (spheres.IsEmpty)
        {
            return CellId.None;
        }

        return fidelity.Precision == OutdoorPrecision.Double
            ? ContainingCell.PickOutdoorDouble(array, position, spheres[0].Center, policy, current)
            : ContainingCell.PickOutdoor(array, position, spheres[0].Center, policy, current);
    }
}
