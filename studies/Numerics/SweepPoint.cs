using AcPhys.Core;

namespace AcPhys.Studies.Numerics;

/// <summary>One point of a numeric sweep: a position's cell id and a block-frame point in that id's frame.</summary>
/// <param name="Cell">The position's cell id.</param>
/// <param name="X">Block-frame x.</param>
/// <param name="Y">Block-frame y.</param>
public readonly record struct SweepPoint(CellId Cell, float X, float Y)
{
    /// <inheritdoc/>
    public override string ToString() => $"cell={Cell} x={AcPhys.Formats.Cases.FloatText.Format(X)} y={AcPhys.Formats.Cases.FloatText.Format(Y)}";
}
