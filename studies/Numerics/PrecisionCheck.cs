using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Studies.Invariants;

namespace AcPhys.Studies.Numerics;

/// <summary>How one implementation's answer to an outdoor query compares with the exact answer.</summary>
/// <param name="CellsDiffer">The cell sets differ (as sets).</param>
/// <param name="PickDiffers">The containing cells differ.</param>
/// <param name="Roundings">The float32 roundings the query meets (<see cref="Rounding"/>), which explain a disagreement.</param>
/// <param name="Detail">Both answers, for a report.</param>
public sealed record PrecisionComparison(bool CellsDiffer, bool PickDiffers, IReadOnlyList<string> Roundings, string Detail)
{
    /// <summary>Gets a value indicating whether the answers agree.</summary>
    public bool Agrees => !CellsDiffer && !PickDiffers;

    /// <summary>
    /// Gets a value indicating whether a disagreement is explained (true when they agree): a different cell set only by
    /// a re-base or 24 − r rounding, a different pick over the same cells only by the pick's re-framing rounding.
    /// </summary>
    public bool Explained => Reason != "unexplained";

    /// <summary>Gets the explaining rounding (max-rad before rebase for the cells; reframe for the pick), "none" when they agree, or "unexplained".</summary>
    public string Reason => (CellsDiffer, PickDiffers) switch
    {
        (false, false) => "none",
        (true, _) when Roundings.Contains(Rounding.MaxRad) => Rounding.MaxRad,
        (true, _) when Roundings.Contains(Rounding.Rebase) => Rounding.Rebase,
        (false, true) when Roundings.Contains(Rounding.Reframe) => Rounding.Reframe,
        _ => "unexplained",
    };
}

/// <summary>Compares an implementation's outdoor answer (cells and retail pick) with <see cref="ExactOutdoor"/>.</summary>
public static class PrecisionCheck
{
    /// <summary>Compares one query.</summary>
    /// <param name="impl">The implementation (retail pick).</param>
    /// <param name="c">The query.</param>
    /// <returns>The comparison, or null when the exact oracle does not apply (a non-finite radius).</returns>
    public static PrecisionComparison? Compare(ICellPhysics impl, OutdoorCase c)
    {
        // An env, block-id or id-0 position is seeded as itself (facts §4 step 3): not an arithmetic question.
        if (!c.Cell.IsLand || ExactOutdoor.FindCell(c.Cell, c.Origin, c.Spheres) is not var (cells, containing))
        {
            return null;
        }

        var got = impl.FindCell(c.Cell, c.Origin, c.Spheres, CellId.None);
        bool cellsDiffer = !got.Cells.ToHashSet().SetEquals(cells);
        bool pickDiffers = got.Containing != containing;
        string detail = cellsDiffer || pickDiffers
            ? $"{impl.Name}: [{string.Join(", ", got.Cells)}] pick {got.Containing}; exact: [{string.Join(", ", cells)}] pick {containing}"
            : string.Empty;
        return new PrecisionComparison(cellsDiffer, pickDiffers, cellsDiffer || pickDiffers ? Rounding.Of(c) : [], detail);
    }
}
