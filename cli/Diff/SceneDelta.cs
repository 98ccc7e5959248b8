using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Cli.Diff;

/// <summary>
/// Names the shape of an indoor find_cell difference in the words indoor bugs leave behind: which kind of cell
/// (land or env) is missing or extra, which kind the containing cell is on each side (a port whose outdoor cell wins
/// over the building's room answers a land cell where retail answers an env cell, facts §5), and the load-hint flags
/// and HitsInteriorCell when the cells agree.
/// </summary>
internal static class SceneDelta
{
    /// <summary>Describes how <paramref name="got"/> differs from <paramref name="want"/>, or null when they agree.</summary>
    /// <param name="got">The implementation's answer.</param>
    /// <param name="want">The reference's answer.</param>
    /// <param name="home">The cell the query was asked from.</param>
    /// <returns>The shape, or null.</returns>
    public static string? Of(FindCellResult got, FindCellResult want, CellId home)
    {
        if (!got.Cells.SequenceEqual(want.Cells))
        {
            var missing = want.Cells.Except(got.Cells).ToArray();
            var extra = got.Cells.Except(want.Cells).ToArray();
            return (missing.Length, extra.Length) switch
            {
                (0, 0) => got.Cells.Count != got.Cells.Distinct().Count() ? "duplicate cells" : "same cells, other order",
                (_, 0) => $"missing {Kind(missing)} cells" + (missing.All(c => c.IsEnv) ? string.Empty : $" ({Where(missing, home)})"),
                (0, _) => $"extra {Kind(extra)} cells",
                _ => $"missing {Kind(missing)} and extra {Kind(extra)} cells",
            };
        }

        if (got.Containing != want.Containing)
        {
            return Kind(got.Containing) == Kind(want.Containing)
                ? $"containing another {(got.Containing.IsEnv ? "env" : "land")} cell than the reference"
                : $"containing {Kind(got.Containing)}, reference {Kind(want.Containing)}";
        }

        if (got.Loaded is { } gl && want.Loaded is { } wl && !gl.SequenceEqual(wl))
        {
            return "same cells, other load-hint flags";
        }

        return got.HitsInteriorCell is bool gh && want.HitsInteriorCell is bool wh && gh != wh ? $"HitsInteriorCell {(gh ? "true" : "false")}, reference {(wh ? "true" : "false")}" : null;
    }

    private static string Kind(CellId c) => c.IsNone ? "none" : c.IsEnv ? "an env cell" : "a land cell";

    private static string Kind(IReadOnlyCollection<CellId> cells) =>
        cells.All(c => c.IsEnv) ? "env" : cells.Any(c => c.IsEnv) ? "land and env" : "land";

    private static string Where(IEnumerable<CellId> cells, CellId home) =>
        cells.Where(c => !c.IsEnv).All(c => c.Landblock == home.Landblock) ? "same block" : "other block";
}
