using System.Numerics;

namespace AcPhys.Core;

/// <summary>The outdoor pick in the double-precision reference (<see cref="OutdoorPrecision.Double"/>).</summary>
public static partial class ContainingCell
{
    /// <summary>
    /// Picks as <see cref="PickOutdoor"/> does (closed squares, last hit wins, optional current-first), but re-expresses
    /// the centre in each candidate's frame in double, where the whole-block offset is exact (retail rounds it to float32).
    /// </summary>
    /// <param name="array">The candidates, in insertion order.</param>
    /// <param name="position">The position whose block frame <paramref name="center"/> is in.</param>
    /// <param name="center">Sphere 0's centre.</param>
    /// <param name="policy">Retail or current-cell-first.</param>
    /// <param name="current">The current cell; <see cref="CellId.None"/> when none.</param>
    /// <returns>The containing cell, or <see cref="CellId.None"/>.</returns>
    public static CellId PickOutdoorDouble(CellArray array, CellId position, Vector3 center, PickPolicy policy, CellId current)
    {
        if (policy == PickPolicy.CurrentFirst && current.IsLand)
        {
            int i = array.IndexOf(current);
            if (i >= 0 && array[i].Loaded && ContainsDouble(position, current, center))
            {
                return current;
            }
        }

        var pick = CellId.None;
        for (int i = 0; i < array.Count; i++)
        {
            var entry = array[i];
            if (entry.Loaded && entry.Id.IsLand && ContainsDouble(position, entry.Id, center))
            {
                pick = entry.Id;
            }
        }

        return pick;
    }

    // The square's edges in the position's frame are integers, so every comparison with a float32 centre is exact.
    private static bool ContainsDouble(CellId position, CellId cell, Vector3 center)
    {
        int idx = cell.Low - 1;
        double west = (LandDefs.BlockLength * (cell.BlockX - position.BlockX)) + (LandDefs.CellLength * (idx >> 3));
        double south = (LandDefs.BlockLength * (cell.BlockY - position.BlockY)) + (LandDefs.CellLength * (idx & 7));
        return center.X >= west && center.X <= west + LandDefs.CellLength && center.Y >= south && center.Y <= south + LandDefs.CellLength;
    }
}
