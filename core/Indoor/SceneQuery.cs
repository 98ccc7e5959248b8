using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// The full <c>find_cell_list</c> (facts §4) over a scene: reset, seed, transit closure breadth-first in insertion
/// order, containing pick (interior wins: the first env hit; outdoor: the last hit), and the indoor visibility filter.
/// Allocation-free once the array has grown (the filter's snapshot lives on the stack for up to 256 cells).
/// </summary>
public static class SceneQuery
{
    /// <summary>Runs find_cell_list.</summary>
    /// <param name="array">Reused output array.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The position's cell id: land, env (or a block id, which counts as indoor, facts §1.1).</param>
    /// <param name="spheres">Sphere centres in the position's block frame; sphere 0 decides the pick.</param>
    /// <param name="current">The current cell, for <see cref="PickPolicy.CurrentFirst"/>.</param>
    /// <param name="options">Pick, filter and fidelity.</param>
    /// <returns>The containing cell and the interior flag.</returns>
    public static CellQueryResult FindCellList(CellArray array, IScene scene, CellId position, ReadOnlySpan<Sphere> spheres, CellId current, CellQueryOptions options)
    {
        var fidelity = options.Fidelity;
        if (fidelity.AceKeepsStaleCells)
        {
            array.AddedOutside = false; // ACE: NumCells = 0 but the dictionary keeps earlier entries (facts §7 #6)
        }
        else
        {
            array.Reset();
        }

        bool hits = false;
        bool indoor = position.IsIndoorByLowWord;
        bool visible;
        if (indoor)
        {
            visible = scene.GetEnvCell(position) is not null;
            hits = true;
            array.Add(position, visible);
        }
        else
        {
            visible = !position.IsNone && position.IsLand && scene.IsLoaded(position.Landblock);
            OutdoorCells.AddAllOutsideCells(array, position, Vector3.Zero, spheres, scene, fidelity.Outdoor);
        }

        var containing = CellId.None;
        bool interiorPick = false;
        if (visible && !spheres.IsEmpty)
        {
            for (int i = 0; i < array.Count; i++)
            {
                var entry = array[i];
                if (!entry.Loaded)
                {
                    continue;
                }

                if (entry.Id.IsEnv)
                {
                    if (scene.GetEnvCell(entry.Id) is { } env)
                    {
                        EnvTransit.FindTransitCells(array, scene, env, position, spheres, fidelity);
                    }
                }
                else if (entry.Id.IsLand)
                {
                    // LandCell.find_transit_cells: add_all_outside_cells (a no-op once latched), then its building.
                    OutdoorCells.AddAllOutsideCells(array, position, Vector3.Zero, spheres, scene, fidelity.Outdoor);
                    if (scene.GetBuilding(entry.Id) is { } building)
                    {
                        hits |= EnvTransit.FindBuildingTransitCells(array, scene, entry.Id, building, position, spheres, fidelity);
                    }
                }
            }

            if (options.Pick)
            {
                containing = PickContaining(array, scene, position, spheres[0].Center, current, options, out interiorPick);
                hits |= interiorPick;
            }
        }

        bool filterGuard = fidelity.AceFilterOutsideGuard || (visible && !spheres.IsEmpty);
        // ACE's movement transitions filter too (facts §4 step 5, §7 #9): its fresh CellArray has LoadCells false.
        bool loadCells = options.LoadCells && !fidelity.AceTransitionFilters;
        if (!loadCells && indoor && filterGuard && !(fidelity.AceEarlyReturn && interiorPick))
        {
            FilterVisible(array, scene, position);
        }

        return new CellQueryResult(containing, hits);
    }

    /// <summary>Tests whether a loaded candidate contains a point given in the position's block frame.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The position whose block frame <paramref name="p"/> is in.</param>
    /// <param name="cell">A land or env cell.</param>
    /// <param name="p">The point.</param>
    /// <param name="fidelity">Retail or ACE (facts §7 #13).</param>
    /// <returns>True when the cell contains it.</returns>
    public static bool Contains(IScene scene, CellId position, CellId cell, Vector3 p, IndoorFidelity fidelity)
    {
        var local = p - LandDefs.GetBlockOffset(position, cell);
        if (cell.IsLand)
        {
            return ContainingCell.LandCellContains(cell, local);
        }

        return scene.GetEnvCell(cell) is { } env && env.PointInCell(local, fidelity);
    }

    /// <summary>The containing-cell pick (facts §4 step 4b): the first env hit wins; otherwise the last land hit; current-first keeps a current cell that still contains the centre.</summary>
    /// <param name="array">The candidates.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The position whose block frame <paramref name="center"/> is in.</param>
    /// <param name="center">Sphere 0's centre.</param>
    /// <param name="current">The current cell.</param>
    /// <param name="options">Policy and fidelity.</param>
    /// <param name="interior">Whether an env cell was picked.</param>
    /// <returns>The containing cell, or none.</returns>
    public static CellId PickContaining(CellArray array, IScene scene, CellId position, Vector3 center, CellId current, CellQueryOptions options, out bool interior)
    {
        interior = false;
        bool keepLand = false;
        if (options.Policy == PickPolicy.CurrentFirst && !current.IsNone)
        {
            // Current-first keeps interior-wins: a current env cell that still contains the centre stays; a current
            // land cell stays only if no env cell contains the centre (else an "absorbing" outdoor state).
            int at = array.IndexOf(current);
            if (at >= 0 && array[at].Loaded && Contains(scene, position, current, center, options.Fidelity))
            {
                if (current.IsEnv)
                {
                    interior = true;
                    return current;
                }

                keepLand = current.IsLand;
            }
        }

        var pick = CellId.None;
        for (int i = 0; i < array.Count; i++)
        {
            var entry = array[i];
            if (!entry.Loaded || !(entry.Id.IsEnv || entry.Id.IsLand) || !Contains(scene, position, entry.Id, center, options.Fidelity))
            {
                continue;
            }

            pick = entry.Id;
            if (entry.Id.IsEnv)
            {
                interior = true; // the first env hit wins (facts §4 step 4b)
                return pick;
            }
        }

        return keepLand ? current : pick;
    }

    /// <summary>The indoor visibility filter (facts §4 step 5): keeps the position's cell, the loaded cells it sees, and every load hint.</summary>
    /// <param name="array">The array, filtered in place (removal swaps the last entry into the hole).</param>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The (indoor) position.</param>
    public static void FilterVisible(CellArray array, IScene scene, CellId position)
    {
        var visible = scene.GetEnvCell(position);
        // Facts §4 step 5: over a snapshot, keep the starting cell and the loaded cells it sees; load hints stay.
        int n = array.Count;
        Span<CellId> snapshot = n <= 256 ? stackalloc CellId[n] : new CellId[n];
        for (int i = 0; i < n; i++)
        {
            snapshot[i] = array[i].Id;
        }

        foreach (var id in snapshot)
        {
            int at = array.IndexOf(id);
            if (at < 0 || !array[at].Loaded || id == position)
            {
                continue;
            }

            bool seen = visible is not null && visible.Sees(id) && scene.GetEnvCell(id) is not null;
            if (!seen)
            {
                array.Remove(id);
            }
        }
    }
}
