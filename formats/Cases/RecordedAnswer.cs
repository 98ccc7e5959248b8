using AcPhys.Core;

namespace AcPhys.Formats.Cases;

/// <summary>
/// A port's own answer to one query of a walk, as a capture recorded it (the corpus field <c>recorded</c>,
/// docs/corpus-format.md): the cell it held after the query and, when the capture reported them, its candidates.
/// </summary>
/// <param name="Cell">The port's containing cell (its cell after the query; <see cref="CellId.None"/>: none, the cell kept).</param>
/// <param name="Cells">The port's candidates in its order, or null when the capture did not report them.</param>
internal sealed record RecordedAnswer(CellId Cell, IReadOnlyList<CellId>? Cells);
