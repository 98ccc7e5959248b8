using System.Globalization;
using AcPhys.Core;

namespace AcPhys.Spec.Cases;

/// <summary>One outdoor query: a position's cell id and sphere centres in that cell's block frame (facts §0, §3.3).</summary>
/// <param name="Cell">The position's cell id.</param>
/// <param name="Spheres">Spheres, centres in <paramref name="Cell"/>'s block frame; sphere 0 decides the pick.</param>
public sealed record OutdoorCase(CellId Cell, IReadOnlyList<Sphere> Spheres)
{
    /// <summary>Formats the query on one line with round-trip floats.</summary>
    /// <returns>The text.</returns>
    public override string ToString() =>
        $"cell={Cell} spheres=[{string.Join("; ", Spheres.Select(Format))}]";

    /// <summary>Formats one sphere as <c>(x, y, z) r=R</c>.</summary>
    /// <param name="s">The sphere.</param>
    /// <returns>The text.</returns>
    public static string Format(Sphere s) =>
        string.Create(CultureInfo.InvariantCulture, $"({FloatText.Format(s.Center.X)}, {FloatText.Format(s.Center.Y)}, {FloatText.Format(s.Center.Z)}) r={FloatText.Format(s.Radius)}");
}
