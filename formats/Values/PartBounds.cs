using System.Globalization;
using AcPhys.Core;

namespace AcPhys.Formats.Values;

/// <summary>
/// The bounds of a parts query wherever one is read (corpus files, protocol requests, <c>serve</c>): the cells
/// <c>add_cell_block</c> visits grow with the square of the parts' extent (facts §3.4 step 4), so a box of ±1e30 m
/// never finished (issue 28). The bounds hold every retail object and every generated case with room to spare: a
/// landblock is 192 m, generated boxes and radii are at most 15 m, origins within [−30, 222] m, one block.
/// </summary>
internal static class PartBounds
{
    /// <summary>The most parts one query may hold.</summary>
    public const int MaxParts = 256;

    /// <summary>The largest magnitude of a box corner component or a radius, metres.</summary>
    public const float MaxSize = 200f;

    /// <summary>The largest magnitude of an origin's x or y (block frame), metres.</summary>
    public const float MaxOrigin = 500f;

    /// <summary>Returns what is wrong with the number of parts, or null when it is valid.</summary>
    /// <param name="count">The number of parts.</param>
    /// <returns>The problem (no location), or null.</returns>
    public static string? CountProblem(int count) =>
        count is > 0 and <= MaxParts ? null : string.Create(CultureInfo.InvariantCulture, $"expected an array of 1 to {MaxParts} parts (the first is the anchor), got {count:N0}");

    /// <summary>Returns what is wrong with one part's size, place or block, or null when it is within bounds.</summary>
    /// <param name="part">The part.</param>
    /// <param name="first">The query's first part (its block is the reference).</param>
    /// <returns>The field (origin, min, max, radius, cell) and the problem, or null.</returns>
    public static (string Field, string Problem)? Problem(Part part, Part first)
    {
        if (Beyond(part.Frame.Origin.X, MaxOrigin) || Beyond(part.Frame.Origin.Y, MaxOrigin))
        {
            return ("origin", Say($"x and y must be within ±{MaxOrigin} m of the block frame, got ({part.Frame.Origin.X}, {part.Frame.Origin.Y})"));
        }

        if (Beyond(part.Bounds.Min, MaxSize))
        {
            return ("min", Say($"every component must be within ±{MaxSize} m (a landblock is 192 m), got {part.Bounds.Min}"));
        }

        if (Beyond(part.Bounds.Max, MaxSize))
        {
            return ("max", Say($"every component must be within ±{MaxSize} m (a landblock is 192 m), got {part.Bounds.Max}"));
        }

        if (Beyond(part.Radius, MaxSize))
        {
            return ("radius", Say($"must be at most {MaxSize} m (a landblock is 192 m), got {part.Radius}"));
        }

        var here = part.Cell.Landblock;
        var there = first.Cell.Landblock;
        if (Math.Abs(here.X - there.X) > 1 || Math.Abs(here.Y - there.Y) > 1)
        {
            return ("cell", Say($"every part must lie in the first part's block or a neighbour, got {part.Cell} beside {first.Cell}"));
        }

        return null;
    }

    private static bool Beyond(float v, float max) => float.IsFinite(v) && Math.Abs(v) > max;

    private static bool Beyond(System.Numerics.Vector3 v, float max) => Beyond(v.X, max) || Beyond(v.Y, max) || Beyond(v.Z, max);

    private static string Say(FormattableString text) => text.ToString(CultureInfo.InvariantCulture);
}
