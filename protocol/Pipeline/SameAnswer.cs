using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Protocol.Pipeline;

/// <summary>
/// Whether two decoded answers are the same value to every reader: a check that is handed one cannot tell it from the
/// other (floats compared bit for bit, lists element by element, an optional field absent only when absent in both).
/// The pipelined transport accepts a speculated answer only when it is the same as the answer the child sent.
/// </summary>
internal static class SameAnswer
{
    /// <summary>Compares two answers of one operation.</summary>
    /// <param name="a">One answer.</param>
    /// <param name="b">The other.</param>
    /// <returns>True when no reader can tell them apart.</returns>
    public static bool Of(object? a, object? b) => (a, b) switch
    {
        (null, null) => true,
        (AdjustResult x, AdjustResult y) => x.Ok == y.Ok && x.Cell == y.Cell && Bits(x.X) == Bits(y.X) && Bits(x.Y) == Bits(y.Y),
        (FindCellResult x, FindCellResult y) => FindCell(x, y),
        (IReadOnlyList<FindCellResult> x, IReadOnlyList<FindCellResult> y) => x.Count == y.Count && x.Zip(y).All(p => FindCell(p.First, p.Second)),
        (IReadOnlyList<CellId> x, IReadOnlyList<CellId> y) => x.SequenceEqual(y),
        (string x, string y) => string.Equals(x, y, StringComparison.Ordinal),
        (bool x, bool y) => x == y,
        (CellId x, CellId y) => x == y,
        (ValueTuple<bool, int, int> x, ValueTuple<bool, int, int> y) => x == y,
        _ => false, // an answer of another shape is never the same
    };

    private static int Bits(float f) => BitConverter.SingleToInt32Bits(f);

    private static bool FindCell(FindCellResult x, FindCellResult y) =>
        x.Containing == y.Containing
        && x.HitsInteriorCell == y.HitsInteriorCell
        && x.Cells.SequenceEqual(y.Cells)
        && (x.Loaded is null ? y.Loaded is null : y.Loaded is not null && x.Loaded.SequenceEqual(y.Loaded));
}
