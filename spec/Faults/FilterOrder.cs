using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// How a port's visibility filter removes entries (facts §4 step 5, §5.9, pitfall 6). Retail walks a snapshot and
/// removes each unkept id by swapping the last entry into its hole, so a removal in the middle changes the order of
/// what follows. The other ways are what ports write instead; each keeps the same entries as retail or (skipping the
/// swapped-in entry) more, in another order.
/// </summary>
internal enum FilterWay
{
    /// <summary>Retail: over a snapshot, remove by id, the last entry moves into the hole (<see cref="SceneQuery.FilterVisible"/>).</summary>
    Retail,

    /// <summary>Order-preserving removal (a List.RemoveAll, a LINQ Where, ACE's Dictionary when nothing is added after a removal).</summary>
    Stable,

    /// <summary>An index loop over the live array that swaps the last entry into the hole and moves on without re-testing it.</summary>
    SkipSwappedIn,

    /// <summary>An index loop from the last entry down to the first, swapping the last entry into each hole.</summary>
    FromEnd,

    /// <summary>An index loop over the live array that swaps the last entry into the hole and re-tests it before moving on.</summary>
    LiveRecheck,
}

/// <summary>The filter's removal loop written each way (<see cref="FilterWay"/>); the keep test is always retail's.</summary>
internal static class FilterOrder
{
    /// <summary>Filters the array in place.</summary>
    /// <param name="array">The candidates.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The (indoor) position.</param>
    /// <param name="way">The removal loop.</param>
    public static void Filter(CellArray array, IScene scene, CellId position, FilterWay way)
    {
        if (way == FilterWay.Retail)
        {
            SceneQuery.FilterVisible(array, scene, position);
            return;
        }

        var entries = new List<CellEntry>(array.Count);
        for (int i = 0; i < array.Count; i++)
        {
            entries.Add(array[i]);
        }

        var visible = scene.GetEnvCell(position);
        bool Keep(CellEntry e) => !e.Loaded || e.Id == position || (visible is not null && visible.Sees(e.Id) && scene.GetEnvCell(e.Id) is not null);
        var kept = way switch
        {
            FilterWay.Stable => [.. entries.Where(Keep)],
            FilterWay.FromEnd => FromEnd(entries, Keep),
            _ => Live(entries, Keep, recheck: way == FilterWay.LiveRecheck),
        };

        array.Reset();
        foreach (var e in kept)
        {
            array.Add(e.Id, e.Loaded);
        }
    }

    /// <summary>Returns the ids the filter would leave, for a copy of the array.</summary>
    /// <param name="array">The unfiltered candidates (not changed).</param>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The (indoor) position.</param>
    /// <param name="way">The removal loop.</param>
    /// <returns>The ids in order.</returns>
    public static CellId[] Filtered(CellArray array, IScene scene, CellId position, FilterWay way)
    {
        var copy = new CellArray(array.Count);
        for (int i = 0; i < array.Count; i++)
        {
            copy.Add(array[i].Id, array[i].Loaded);
        }

        Filter(copy, scene, position, way);
        return copy.ToIdArray();
    }

    private static List<CellEntry> Live(List<CellEntry> a, Func<CellEntry, bool> keep, bool recheck)
    {
        int i = 0;
        while (i < a.Count)
        {
            if (keep(a[i]))
            {
                i++;
                continue;
            }

            a[i] = a[^1];
            a.RemoveAt(a.Count - 1);
            if (!recheck)
            {
                i++; // the swapped-in entry is never tested
            }
        }

        return a;
    }

    private static List<CellEntry> FromEnd(List<CellEntry> a, Func<CellEntry, bool> keep)
    {
        for (int i = a.Count - 1; i >= 0; i--)
        {
            if (!keep(a[i]))
            {
                a[i] = a[^1];
                a.RemoveAt(a.Count - 1);
            }
        }

        return a;
    }
}
