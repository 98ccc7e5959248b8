using System.Globalization;
using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Formats.Cases;

/// <summary>One outdoor query: a position's cell id and sphere centres in that cell's block frame (facts §0, §3.3).</summary>
/// <param name="Cell">The position's cell id.</param>
/// <param name="Spheres">Spheres, centres in <paramref name="Cell"/>'s block frame; sphere 0 decides the pick.</param>
public sealed record OutdoorCase(CellId Cell, IReadOnlyList<Sphere> Spheres)
{
    /// <summary>
    /// Gets the position's own point in <see cref="Cell"/>'s block frame. Retail reads it only when the sphere list is
    /// empty: add_all_outside_cells then re-seats the position itself and adds its one cell (facts §3.3 step 3).
    /// </summary>
    public Vector3 Origin { get; init; }

    /// <summary>Formats the query on one line with round-trip floats.</summary>
    /// <returns>The text.</returns>
    public override string ToString() =>
        $"cell={Cell} spheres=[{string.Join("; ", Spheres.Select(Format))}]" + (Spheres.Count == 0 ? string.Create(CultureInfo.InvariantCulture, $" origin=({FloatText.Format(Origin.X)}, {FloatText.Format(Origin.Y)}, {FloatText.Format(Origin.Z)})") : string.Empty);

    /// <summary>Formats one sphere as <c>(x, y, z) r=R</c>.</summary>
    /// <param name="s">The sphere.</param>
    /// <returns>The text.</returns>
    public static string Format(Sphere s) =>
        string.Create(CultureInfo.InvariantCulture, $"({FloatText.Format(s.Center.X)}, {FloatText.Format(s.Center.Y)}, {FloatText.Format(s.Center.Z)}) r={FloatText.Format(s.Radius)}");
}
