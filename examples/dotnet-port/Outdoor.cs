using AcPhys.Core;

namespace ExamplePort;

/// <summary>The outdoor cell sets (facts §3.1–§3.3) and the open-land containing-cell pick (facts §4, §5.5).</summary>
/// <param name="grid">The LandDefs functions.</param>
/// <param name="bug">The seeded bug, if any.</param>
public sealed class Outdoor(Grid grid, Bug bug)
{
    /// <summary>Returns the land cells the spheres touch, in insertion order (add_all_outside_cells, sphere variant).</summary>
    /// <param name="cell">The position's cell.</param>
    /// <param name="origin">The position's own point, used only when there is no sphere.</param>
    /// <param name="spheres">Centres in the cell's block frame.</param>
    /// <returns>The cells.</returns>
    public List<CellId> Cells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres)
    {
        var cells = new List<CellId>();
        if (spheres.Count == 0)
        {
            // No sphere: the position's own column (on a copy of the position, as retail).
            if (grid.Reseat(cell, origin.X, origin.Y) is { Ok: true } only && grid.CellLcoord(only.Cell) is Lcoord lc)
            {
                Add(cells, lc, lc.X, lc.Y);
            }

            return cells;
        }

        foreach (var sphere in spheres)
        {
            var seat = grid.Reseat(cell, sphere.Center.X, sphere.Center.Y);
            if (!seat.Ok || grid.CellLcoord(seat.Cell) is not Lcoord home)
            {
                break; // a sphere off the map ends the loop; cells already added stay (facts §3.3 b)
            }

            Add(cells, home, home.X, home.Y);
            Neighbours(cells, home, InCell(seat.X), InCell(seat.Y), sphere.Radius, 24f - sphere.Radius);
        }

        return cells;
    }

    /// <summary>Returns the last candidate whose closed 24 m square holds sphere 0's centre (retail's pick), or id 0.</summary>
    /// <param name="cell">The position's cell (the centre is in its block frame).</param>
    /// <param name="cells">The candidates, in order.</param>
    /// <param name="centre">Sphere 0's centre.</param>
    /// <returns>The containing cell.</returns>
    public CellId Pick(CellId cell, IReadOnlyList<CellId> cells, System.Numerics.Vector3 centre)
    {
        var pick = default(CellId);
        foreach (var candidate in cells)
        {
            if (grid.CellLcoord(candidate) is not Lcoord lc)
            {
                continue;
            }

            // Into the candidate's block frame by 192 m per block of difference, in float32 (facts §5.8).
            float dx = 192f * (int)((candidate.Value >> 24) - (cell.Value >> 24));
            float dy = 192f * (int)(((candidate.Value >> 16) & 0xFF) - ((cell.Value >> 16) & 0xFF));
            float px = centre.X - dx, py = centre.Y - dy;
            float west = 24f * (lc.X % 8), south = 24f * (lc.Y % 8);
            if (px >= west && px <= west + 24f && py >= south && py <= south + 24f)
            {
                pick = candidate; // the last one wins: shared edges belong to every adjacent cell (facts §4 step 4b)
            }
        }

        return pick;
    }

    // The neighbours a sphere reaches, strict comparisons, in retail's order (facts §3.2).
    private void Neighbours(List<CellId> cells, Lcoord home, float px, float py, float near, float far)
    {
        int x = home.X, y = home.Y;
        if (px > far)
        {
            Add(cells, home, x + 1, y);
            if (py > far)
            {
                Add(cells, home, x + 1, y + 1);
            }

            if (py < near)
            {
                Add(cells, home, x + 1, y - 1);
            }
        }

        if (px < near)
        {
            Add(cells, home, x - 1, y);
            if (py > far)
            {
                Add(cells, home, x - 1, y + 1);
            }

            if (py < near)
            {
                Add(cells, home, x - 1, y - 1);
            }
        }

        if (py > far)
        {
            Add(cells, home, x, y + 1);
        }

        if (py < near)
        {
            Add(cells, home, x, y - 1);
        }
    }

    private void Add(List<CellId> cells, Lcoord home, int x, int y)
    {
        if (bug == Bug.Clamp106 && (x / 8 != home.X / 8 || y / 8 != home.Y / 8))
        {
            return; // the #106 freeze: a neighbour across the block line is never a candidate
        }

        var id = grid.CellAt(x, y);
        if (id.Value != 0 && !cells.Contains(id))
        {
            cells.Add(id);
        }
    }

    // The point inside its 24 m cell, [0, 24): exact for a block-frame value in [0, 192).
    private static float InCell(float v) => (float)(v - (24.0 * Math.Floor(v / 24.0)));
}
