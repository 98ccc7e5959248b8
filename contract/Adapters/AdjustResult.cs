using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>The outcome of <c>adjust_to_outside</c>: success flag, the re-seated id and the (snapped, re-based) x, y.</summary>
/// <param name="Ok">True when the point was re-seated to a land cell.</param>
/// <param name="Cell">The land cell on success; <see cref="CellId.None"/> on failure.</param>
/// <param name="X">Block-frame x after the call.</param>
/// <param name="Y">Block-frame y after the call.</param>
public readonly record struct AdjustResult(bool Ok, CellId Cell, float X, float Y);
