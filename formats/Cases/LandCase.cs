using System.Globalization;
using AcPhys.Core;

namespace AcPhys.Formats.Cases;

/// <summary>
/// One input to the LandDefs invariants: a cell id, a block-frame point (x, y) in that id's block, and an lcoord.
/// Each invariant reads the fields it needs; one case type lets props, the fuzzer and the CLI share every check.
/// </summary>
/// <param name="Cell">Any 32-bit id.</param>
/// <param name="X">Block-frame x, float32 as retail (any value, NaN included).</param>
/// <param name="Y">Block-frame y.</param>
/// <param name="Lcoord">Any pair of ints (off-map values included).</param>
public readonly record struct LandCase(CellId Cell, float X, float Y, Lcoord Lcoord)
{
    /// <summary>Formats the case on one line with round-trip floats, e.g. <c>cell=0xA9B40031 x=150 y=-0.5 lcoord=(3, 4)</c>.</summary>
    /// <returns>The text.</returns>
    public override string ToString() =>
        $"cell={Cell} x={FloatText.Format(X)} y={FloatText.Format(Y)} lcoord={Lcoord}";
}

/// <summary>Formats float32 values so that they parse back to the same bits (round-trip), non-finite as NaN/Infinity/-Infinity.</summary>
public static class FloatText
{
    /// <summary>Formats a float32 in its shortest round-trip form.</summary>
    /// <param name="value">The value.</param>
    /// <returns>The text; <c>-0</c> keeps its sign.</returns>
    public static string Format(float value) => value.ToString("R", CultureInfo.InvariantCulture);
}
