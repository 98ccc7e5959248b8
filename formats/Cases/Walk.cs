using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Formats.Cases;

/// <summary>A sphere of a moving body: offset from the body's position, and radius.</summary>
/// <param name="Offset">Offset from the position, metres.</param>
/// <param name="Radius">Radius, metres.</param>
public readonly record struct BodySphere(Vector3 Offset, float Radius);

/// <summary>
/// A walk: a start (cell id + block-local position), a body of spheres, and a list of horizontal moves. Each step
/// moves the body by one delta in the current cell's block frame; the runner then asks find_cell and re-frames.
/// </summary>
/// <param name="StartCell">The start cell; its block frame is the frame of <paramref name="Start"/>.</param>
/// <param name="Start">Block-frame start position.</param>
/// <param name="Body">The spheres; sphere 0 decides the containing cell.</param>
/// <param name="Steps">Moves (dx, dy), metres.</param>
public sealed record Walk(CellId StartCell, Vector3 Start, IReadOnlyList<BodySphere> Body, IReadOnlyList<Vector2> Steps)
{
    /// <summary>Returns the spheres of the body at a block-frame position.</summary>
    /// <param name="position">The position.</param>
    /// <returns>Spheres with centres in the same frame.</returns>
    public Sphere[] SpheresAt(Vector3 position) => Body.Select(b => new Sphere(position + b.Offset, b.Radius)).ToArray();

    /// <summary>Gets a value indicating whether the start lies in its start cell's block, x, y ∈ [0, 192), as a client's position always does.</summary>
    public bool StartsInBlock => Start.X >= 0 && Start.X < LandDefs.BlockLength && Start.Y >= 0 && Start.Y < LandDefs.BlockLength;

    /// <summary>
    /// Re-expresses the start in the block that contains it (world position unchanged, exact by whole blocks) and
    /// names the land cell under it as the start cell, as a client holds its position; clamps into the map's edge blocks.
    /// </summary>
    /// <returns>The normalised walk.</returns>
    public Walk Normalised()
    {
        int bx = StartCell.BlockX, by = StartCell.BlockY;
        float x = Start.X, y = Start.Y;
        (bx, x) = Normalise(bx, x);
        (by, y) = Normalise(by, y);
        var cell = LandDefs.LcoordToGid((bx * 8) + (int)MathF.Floor(x / 24f), (by * 8) + (int)MathF.Floor(y / 24f));
        return this with { StartCell = cell, Start = new Vector3(x, y, Start.Z) };
    }

    private static (int Block, float V) Normalise(int block, float v)
    {
        while (v < 0 && block > 0)
        {
            block--;
            v += LandDefs.BlockLength;
        }

        while (v >= LandDefs.BlockLength && block < LandDefs.MaxBlockByte)
        {
            block++;
            v -= LandDefs.BlockLength;
        }

        return (block, Math.Clamp(v, 0f, MathF.BitDecrement(LandDefs.BlockLength)));
    }

    /// <summary>Formats the walk on one line.</summary>
    /// <returns>The text.</returns>
    public override string ToString() =>
        $"start {StartCell} ({FloatText.Format(Start.X)}, {FloatText.Format(Start.Y)}, {FloatText.Format(Start.Z)}), " +
        $"body [{string.Join("; ", Body.Select(b => $"+({FloatText.Format(b.Offset.X)}, {FloatText.Format(b.Offset.Y)}, {FloatText.Format(b.Offset.Z)}) r={FloatText.Format(b.Radius)}"))}], " +
        $"steps [{string.Join("; ", Steps.Select(s => $"{FloatText.Format(s.X)}, {FloatText.Format(s.Y)}"))}]";
}
