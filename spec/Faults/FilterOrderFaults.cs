namespace AcPhys.Spec.Faults;

/// <summary>
/// Planted faults of the visibility filter's removal loop (issue #27, facts §4 step 5, §5.9, pitfall 6): the keep test
/// is retail's, the order of what is left is not. Run by <see cref="FaultySceneQuery"/> through <see cref="FilterOrder"/>.
/// Two more loops a port may write answer exactly as the in-place loop with re-test does on every keep/remove pattern
/// of up to 8 entries (filling each hole with the last entry that will be kept; a two-pointer partition), so they are
/// not separate faults.
/// </summary>
internal static class FilterOrderFaults
{
    /// <summary>Order-preserving filter.</summary>
    public static readonly PlantedFault StableOrder = new(
        "filter-stable-order",
        "the visibility filter keeps the survivors in their original order (order-preserving removal) instead of swapping the last entry into each hole",
        "facts §5.9, §4 step 5, pitfall 6: retail's CCellArray::remove_cell moves the last element into the hole, so removing a land cell from the middle of the array changes the order of the cells behind it; a port that filters with List.RemoveAll or a LINQ Where (or keeps ACE's Dictionary, whose order survives removals) keeps them in insertion order.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Index loop that skips the swapped-in entry.</summary>
    public static readonly PlantedFault SkipsSwappedIn = new(
        "filter-skips-swapped-in",
        "the visibility filter swaps the last entry into a hole and moves on to the next index without testing the entry it swapped in",
        "facts §5.9, §4 step 5: an in-place translation of the snapshot loop into `for (i = 0; i < n; i++) if (!keep(a[i])) remove_at(i)` with swap-removal never tests the entry moved into the hole, so a second land cell or an unseen room at the end of the array survives a static query.",
        ["VISIBILITY", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Filter from the end.</summary>
    public static readonly PlantedFault FromEnd = new(
        "filter-from-end",
        "the visibility filter walks the array from the last entry to the first, swapping the last entry into each hole",
        "facts §5.9, §4 step 5: walking backwards is the textbook way to remove while iterating; with swap-removal every entry swapped in has already been kept, so the survivors come out in another order than retail's front-to-back snapshot loop leaves them whenever two or more entries go.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Live index loop with re-test.</summary>
    public static readonly PlantedFault LiveRecheck = new(
        "filter-live-recheck",
        "the visibility filter walks the live array by index, swaps the last entry into each hole and re-tests it before moving on",
        "facts §5.9, §4 step 5: the same survivors as retail's snapshot loop, but an entry swapped in is removed at once instead of when the snapshot reaches it, so with three or more removals (one of them the last entry) the survivors' order differs.",
        ["FIND-CELL-CONFORMANCE"]);

    /// <summary>Gets every fault of this list.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [StableOrder, SkipsSwappedIn, FromEnd, LiveRecheck];

    /// <summary>Returns the filter loop a fault plants.</summary>
    /// <param name="defect">The defect.</param>
    /// <returns>The loop (retail for any other defect).</returns>
    internal static FilterWay WayOf(IndoorDefect defect) => defect switch
    {
        IndoorDefect.FilterStableOrder => FilterWay.Stable,
        IndoorDefect.FilterSkipsSwappedIn => FilterWay.SkipSwappedIn,
        IndoorDefect.FilterFromEnd => FilterWay.FromEnd,
        IndoorDefect.FilterLiveRecheck => FilterWay.LiveRecheck,
        _ => FilterWay.Retail,
    };

    /// <summary>Returns the defect a fault of this list plants.</summary>
    /// <param name="fault">A fault.</param>
    /// <returns>The defect, or none.</returns>
    internal static IndoorDefect DefectOf(PlantedFault fault) => fault.Id switch
    {
        "filter-stable-order" => IndoorDefect.FilterStableOrder,
        "filter-skips-swapped-in" => IndoorDefect.FilterSkipsSwappedIn,
        "filter-from-end" => IndoorDefect.FilterFromEnd,
        "filter-live-recheck" => IndoorDefect.FilterLiveRecheck,
        _ => IndoorDefect.None,
    };
}
