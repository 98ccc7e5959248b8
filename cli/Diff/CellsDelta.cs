using AcPhys.Core;

namespace AcPhys.Cli.Diff;

/// <summary>
/// Names the shape of the difference between two answers (cell lists, containing cells) in words that separate root
/// causes: a port that clamps candidates to the position's landblock misses cells <em>in another block</em>, a port
/// with an inclusive edge test adds <em>extra</em> cells, a port that sorts its set answers the same cells <em>in
/// another order</em>.
/// </summary>
internal static class CellsDelta
{
    /// <summary>Describes how <paramref name="mine"/> differs from <paramref name="theirs"/>, or null when they are equal.</summary>
    /// <param name="mine">The implementation's cells, in insertion order.</param>
    /// <param name="theirs">The reference's cells, in insertion order.</param>
    /// <param name="home">The cell whose landblock the query was asked in (to say whether the difference lies in another block).</param>
    /// <returns>The shape, or null.</returns>
    public static string? Of(IReadOnlyList<CellId> mine, IReadOnlyList<CellId> theirs, CellId home)
    {
        if (mine.SequenceEqual(theirs))
        {
            return null;
        }

        var missing = theirs.Except(mine).ToArray();
        var extra = mine.Except(theirs).ToArray();
        if (missing.Length == 0 && extra.Length == 0)
        {
            return mine.Count != mine.Distinct().Count() ? "duplicate cells" : "same cells, other order";
        }

        // Only missing cells say where they lie: a port that clamps candidates to the position's landblock misses
        // exactly the cells of other blocks (the 10,449-frame freeze), while extra cells lie wherever the edge was touched.
        return missing.Length == 0 ? "extra cells"
            : extra.Length == 0 ? $"missing cells ({Where(missing, home)})"
            : $"missing and extra cells (missing: {Where(missing, home)})";
    }

    /// <summary>Describes how two containing cells differ, or null when they are equal.</summary>
    /// <param name="mine">The implementation's containing cell.</param>
    /// <param name="theirs">The reference's containing cell.</param>
    /// <returns>The shape, or null.</returns>
    public static string? Containing(CellId mine, CellId theirs) =>
        mine == theirs ? null
        : mine.IsNone ? "containing none (reference has one)"
        : theirs.IsNone ? "containing a cell (reference has none)"
        : mine.Landblock == theirs.Landblock ? "other containing cell (same block)"
        : "other containing cell (other block)";

    /// <summary>
    /// Names the class of a find_cell difference, or null when both parts agree: the cells' shape when the cells differ
    /// (a wrong containing cell then mostly follows from them), else the containing cell's.
    /// </summary>
    /// <param name="cells">The cells' shape.</param>
    /// <param name="containing">The containing cell's shape.</param>
    /// <returns>The text.</returns>
    public static string? Class(string? cells, string? containing) => cells ?? containing;

    private static string Where(IEnumerable<CellId> cells, CellId home)
    {
        bool same = false, other = false;
        foreach (var c in cells)
        {
            if (c.Landblock == home.Landblock)
            {
                same = true;
            }
            else
            {
                other = true;
            }
        }

        return same && other ? "this and other blocks" : other ? "other block" : "same block";
    }
}
