using System.Numerics;

namespace AcPhys.Core;

/// <summary>The outdoor containing-cell pick of <c>find_cell_list</c> (facts §4 step 4b, §5.5).</summary>
public static partial class ContainingCell
{
    /// <summary>
    /// Picks the land cell containing sphere 0's centre among the loaded land cells of the array: closed 24 m squares,
    /// the centre re-expressed in each candidate's block frame (GetBlockOffset), last hit wins (facts §6.5 ties).
    /// </summary>
    /// <param name="array">The candidates, in insertion order.</param>
    /// <param name="position">The position whose block frame <paramref name="center"/> is in.</param>
    /// <param name="center">Sphere 0's centre.</param>
    /// <param name="policy">Retail or current-cell-first.</param>
    /// <param name="current">The current cell (used by <see cref="PickPolicy.CurrentFirst"/>); <see cref="CellId.None"/> when none.</param>
    /// <returns>The containing cell, or <see cref="CellId.None"/> when no candidate contains the centre.</returns>
    public static CellId PickOutdoor(CellArray array, CellId position, Vector3 center, PickPolicy policy, CellId current)
    {
        if (policy == PickPolicy.CurrentFirst && current.IsLand)
        {
            int i = array.IndexOf(current);
            if (i >= 0 && array[i].Loaded && LandCellContains(current, center - LandDefs.GetBlockOffset(position, current)))
            {
                return current;
            }
        }

        var pick = CellId.None;
        for (int i = 0; i < array.Count; i++)
        {
            var entry = array[i];
            if (!entry.Loaded || !entry.Id.IsLand)
            {
                continue;
            }

            if (LandCellContains(entry.Id, center - LandDefs.GetBlockOffset(position, entry.Id)))
            {
                pick = entry.Id;
            }
        }

        return pick;
    }

    /// <summary>
    /// Tests a block-frame point against a land cell as retail's <c>point_in_cell</c> does (facts §5.5): float32
    /// <c>point_in_poly2D</c> over the two terrain triangles (<see cref="TerrainTriangles"/>). Up to rounding the union is
    /// the closed square, so shared edges belong to every adjacent cell; z is ignored.
    /// </summary>
    /// <param name="cell">A land cell id.</param>
    /// <param name="p">A point in the cell's block frame.</param>
    /// <returns>True when inside or on the cell.</returns>
    public static bool LandCellContains(CellId cell, Vector3 p) => TerrainTriangles.Contains(cell, p);
}
