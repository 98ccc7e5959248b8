using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Issue 41's scene pieces: box cells laid out in the block frame, each in a frame of its own (an origin off the
/// block's grid, unturned or turned half round), their boxes and portal planes expressed in that frame; a half turn is
/// the quaternion (0, 0, 1, 0) exactly, so float32 GlobalToLocal negates x and y without rounding (facts §5.8).
/// </summary>
public static class CellFrameKit
{
    /// <summary>Gets the exact half turn about +z.</summary>
    public static Quaternion HalfTurn { get; } = new(0, 0, 1, 0);

    /// <summary>Returns a cell's frame.</summary>
    /// <param name="origin">Origin, block frame.</param>
    /// <param name="turned">Whether the frame is turned half round.</param>
    /// <returns>The frame.</returns>
    public static Frame FrameOf(Vector3 origin, bool turned) => new(origin, turned ? HalfTurn : Quaternion.Identity);

    /// <summary>Returns a box given in the block frame as a piece in a frame.</summary>
    /// <param name="frame">The cell's frame.</param>
    /// <param name="min">Block-frame minimum.</param>
    /// <param name="max">Block-frame maximum.</param>
    /// <returns>The piece.</returns>
    public static ScenePiece Box(Frame frame, Vector3 min, Vector3 max)
    {
        Vector3 a = frame.GlobalToLocal(min), b = frame.GlobalToLocal(max);
        return ScenePiece.FromBox(Vector3.Min(a, b), Vector3.Max(a, b));
    }

    /// <summary>Returns a portal plane given in the block frame, expressed in a frame.</summary>
    /// <param name="frame">The cell's frame.</param>
    /// <param name="normal">Block-frame normal (an axis).</param>
    /// <param name="point">A block-frame point on the plane.</param>
    /// <returns>The plane.</returns>
    public static CellPlane Plane(Frame frame, Vector3 normal, Vector3 point) =>
        CellPlane.Through(Vector3.Transform(normal, Quaternion.Conjugate(frame.Rotation)), frame.GlobalToLocal(point));

    /// <summary>Returns a block and its eight neighbours (those on the map), all loaded.</summary>
    /// <param name="home">The block.</param>
    /// <returns>The blocks.</returns>
    public static List<LandblockId> BlocksAround(LandblockId home)
    {
        var blocks = new List<LandblockId> { home };
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                int x = home.X + dx, y = home.Y + dy;
                if ((dx, dy) != (0, 0) && x >= 0 && y >= 0 && x <= LandDefs.MaxBlockByte && y <= LandDefs.MaxBlockByte)
                {
                    blocks.Add(new LandblockId((byte)x, (byte)y));
                }
            }
        }

        return blocks;
    }

    /// <summary>
    /// Returns a float32 radius r with r + pad == threshold exactly in float32 (retail's R, facts §1.5) whose exact sum
    /// with the padding written as a double literal (0.01, 0.0002) is not above the threshold either, so a port that
    /// computes R in double decides the tie as retail does (docs/conformance.md, "Numerical ties"); NaN when none is.
    /// </summary>
    /// <param name="threshold">The threshold r + pad, a multiple of 1/1024.</param>
    /// <param name="pad">The test's padding (0.01 or EPS).</param>
    /// <returns>The radius, or NaN.</returns>
    public static float RadiusFor(float threshold, float pad)
    {
        double padDouble = Math.Max(pad, pad == 0.01f ? 0.01 : 0.0002);
        float r = threshold - pad;
        for (int k = 0; k < 24; k++)
        {
            r = MathF.BitIncrement(r);
        }

        for (int k = 0; k < 48; k++, r = MathF.BitDecrement(r))
        {
            if (r + pad == threshold && r + padDouble <= threshold)
            {
                return r;
            }
        }

        return float.NaN;
    }

    /// <summary>
    /// Returns the threshold nearest below mesh/1024 (halved when above 505/1024: above 1/2 no float32 radius has the
    /// EPS sum rounding to the threshold from below) that has a radius (<see cref="RadiusFor"/>).
    /// </summary>
    /// <param name="mesh">The starting mesh, 200–1024.</param>
    /// <param name="pad">The padding.</param>
    /// <returns>The threshold.</returns>
    public static float ThresholdFrom(int mesh, float pad)
    {
        for (int m = mesh > 505 ? mesh / 2 : mesh; m >= 64; m--)
        {
            if (!float.IsNaN(RadiusFor(m / 1024f, pad)))
            {
                return m / 1024f;
            }
        }

        throw new InvalidOperationException($"no float32 radius has r + {pad:R} == m/1024 for m up to {mesh}");
    }
}
