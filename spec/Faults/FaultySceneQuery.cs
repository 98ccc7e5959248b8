using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// <c>find_cell_list</c> (facts §4) as a port would write it, with one named defect: reset, seed, transit closure over
/// the growing array, the containing pick and the indoor visibility filter, built from core's public pieces. Retail
/// pick and fidelity; with <see cref="IndoorDefect.None"/> it answers exactly as <see cref="SceneQuery"/> does.
/// </summary>
internal static class FaultySceneQuery
{
    /// <summary>Runs the query.</summary>
    /// <param name="array">The array (reset here).</param>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The position's cell id.</param>
    /// <param name="spheres">Centres in the position's block frame.</param>
    /// <param name="loadCells">True for a movement transition (no visibility filter).</param>
    /// <param name="defect">The defect.</param>
    /// <returns>The containing cell and HitsInteriorCell.</returns>
    public static CellQueryResult FindCellList(CellArray array, IScene scene, CellId position, ReadOnlySpan<Sphere> spheres, bool loadCells, IndoorDefect defect)
    {
        array.Reset();
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
            OutdoorCells.AddAllOutsideCells(array, position, Vector3.Zero, spheres, scene);
        }

        var containing = CellId.None;
        bool interior = false;
        if (visible && !spheres.IsEmpty)
        {
            if (defect == IndoorDefect.PickBeforeTransit)
            {
                containing = Pick(array, scene, position, spheres, defect, out interior);
            }

            // Facts §4 step 4a: the count is re-read each time, so appended cells are walked too (the seed's
            // "snapshot" comment invites reading it once).
            int snapshot = array.Count, hints = 0;
            for (int i = 0; i < (defect == IndoorDefect.SnapshotClosure ? snapshot : HintClosure.Bound(array.Count, hints, defect)); i++)
            {
                var entry = array[i];
                if (!entry.Loaded)
                {
                    // Facts §4 step 4a: a load hint is skipped and the walk goes on (issue 27's faults stop or mis-step here).
                    if (HintClosure.StopsAt(ref i, ref hints, defect))
                    {
                        break;
                    }

                    continue;
                }

                if (entry.Id.IsEnv && scene.GetEnvCell(entry.Id) is { } env)
                {
                    FaultyTransit.FindTransitCells(array, scene, env, position, spheres, defect);
                }
                else if (entry.Id.IsLand)
                {
                    OutdoorCells.AddAllOutsideCells(array, position, Vector3.Zero, spheres, scene);
                    if (scene.GetBuilding(entry.Id) is { } building && InteriorFaults.AsksBuilding(scene, entry.Id, building, position, spheres, defect))
                    {
                        hits |= FaultyTransit.FindBuildingTransitCells(array, scene, entry.Id, building, spheres, defect);
                    }
                }
            }

            if (defect != IndoorDefect.PickBeforeTransit)
            {
                containing = Pick(array, scene, position, spheres, defect, out interior);
            }

            hits |= interior;
        }

        bool skip = defect == IndoorDefect.EarlyReturnUndeclared && interior; // ACE's OC:381 return, retail falls through (facts §7 #7)
        if (!loadCells && indoor && visible && !spheres.IsEmpty && !skip)
        {
            if (defect == IndoorDefect.FilterDropsHints)
            {
                FilterEveryEntry(array, scene, position);
            }
            else
            {
                FilterOrder.Filter(array, scene, position, FilterOrderFaults.WayOf(defect)); // retail unless a filter-order fault (facts §5.9)
            }
        }

        return new CellQueryResult(containing, hits);
    }

    // Facts §4 step 4b: sphere 0's centre; the first env hit wins, else the last land hit.
    private static CellId Pick(CellArray array, IScene scene, CellId position, ReadOnlySpan<Sphere> spheres, IndoorDefect defect, out bool interior)
    {
        var center = defect == IndoorDefect.PickLastSphere ? spheres[^1].Center : spheres[0].Center;
        CellId land = CellId.None, env = CellId.None;
        for (int i = 0; i < array.Count; i++)
        {
            var e = array[i];
            if (!e.Loaded || !(e.Id.IsEnv || e.Id.IsLand) || !SceneQuery.Contains(scene, position, e.Id, center, default))
            {
                continue;
            }

            if (e.Id.IsLand)
            {
                land = e.Id;
            }
            else if (env.IsNone || defect == IndoorDefect.PickLastEnv)
            {
                env = e.Id;
                if (defect != IndoorDefect.PickLastEnv)
                {
                    break;
                }
            }
        }

        interior = !env.IsNone;
        return interior ? env : land;
    }

    // The filter's keep test applied to every entry: a load hint is never a loaded visible cell, so it goes (facts §4 step 5 keeps it).
    private static void FilterEveryEntry(CellArray array, IScene scene, CellId position)
    {
        var visible = scene.GetEnvCell(position);
        foreach (var id in array.ToIdArray())
        {
            if (id != position && !(visible is not null && visible.Sees(id) && scene.GetEnvCell(id) is not null))
            {
                array.Remove(id);
            }
        }
    }
}
