using System.Numerics;

namespace AcPhys.Core;

/// <summary>An axis-aligned box, metres.</summary>
/// <param name="Min">The minimum corner.</param>
/// <param name="Max">The maximum corner.</param>
public readonly record struct Box(Vector3 Min, Vector3 Max)
{
    /// <summary>Returns corner <paramref name="c"/> of 8: bit 0 picks Max.X, bit 1 Max.Y, bit 2 Max.Z (else Min).</summary>
    /// <param name="c">The corner index, 0 to 7.</param>
    /// <returns>The corner.</returns>
    public Vector3 Corner(int c) => new((c & 1) == 0 ? Min.X : Max.X, (c & 2) == 0 ? Min.Y : Max.Y, (c & 4) == 0 ? Min.Z : Max.Z);
}

/// <summary>
/// One physics part of an object, for the parts / bounding-box variant of add_all_outside_cells (facts §3.4): where it
/// is (cell and frame), its local bounding box, its sphere, and whether it is Always2D.
/// </summary>
/// <param name="Cell">The cell id of the part's position; its block frame is the frame of <paramref name="Frame"/>.</param>
/// <param name="Frame">The part's frame in that block frame.</param>
/// <param name="Bounds">The part's bounding box in its own frame.</param>
/// <param name="Radius">The physics (else drawing) sphere's radius, used by Always2D parts.</param>
/// <param name="Always2D">Retail: the part contributes the square [x − r, x + r]² around its raw origin instead of its box.</param>
public readonly record struct Part(CellId Cell, Frame Frame, Box Bounds, float Radius, bool Always2D);
