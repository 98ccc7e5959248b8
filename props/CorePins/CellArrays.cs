using AcPhys.Core;

namespace AcPhys.Props.Mutation;

/// <summary>Reading a <see cref="CellArray"/> in tests: its entries in order, equality with another array, and text.</summary>
internal static class CellArrays
{
    /// <summary>Returns the entries in array order.</summary>
    /// <param name="a">The array.</param>
    /// <returns>Its entries.</returns>
    public static CellEntry[] Entries(CellArray a) => [.. Enumerable.Range(0, a.Count).Select(i => a[i])];

    /// <summary>Tests two arrays for the same entries in the same order and the same outdoor latch.</summary>
    /// <param name="a">One array.</param>
    /// <param name="b">The other.</param>
    /// <returns>True when equal.</returns>
    public static bool Same(CellArray a, CellArray b) => a.AddedOutside == b.AddedOutside && Entries(a).SequenceEqual(Entries(b));

    /// <summary>Returns an array as text, a load hint marked with "?".</summary>
    /// <param name="a">The array.</param>
    /// <returns>The text.</returns>
    public static string Text(CellArray a) => string.Join(",", Entries(a).Select(e => $"{e.Id}{(e.Loaded ? string.Empty : "?")}"));
}
