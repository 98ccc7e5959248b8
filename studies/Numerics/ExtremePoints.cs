using AcPhys.Core;
using AcPhys.Spec.Cases;

namespace AcPhys.Studies.Numerics;

/// <summary>
/// The finite point sets of issue #8's extremes, enumerated whole: every 24 m and 192 m line of the map ± 1..4 ULP
/// in every block frame and its neighbours' frames, block corners, and the special values (EPS band edges, ±1e6,
/// ±float.MaxValue, NaN, ±Inf, −0, subnormals) at the map's edge blocks.
/// </summary>
public static class ExtremePoints
{
    /// <summary>ULP offsets swept around every line: −4..4 (0 is the line itself).</summary>
    public const int MaxUlps = 4;

    /// <summary>Gets the radii every outdoor point is queried with: 0, the smallest subnormal, 0.3 (float32 24 − r rounds up: 23.700001 &gt; 23.69999999), 12, 12 + 1 ULP, 24, 30.</summary>
    public static IReadOnlyList<float> Radii { get; } = [0f, float.Epsilon, 0.3f, 12f, MathF.BitIncrement(12f), 24f, 30f];

    /// <summary>Gets the special coordinate values (each also negated): EPS band edges, huge, non-finite, zeros, subnormals.</summary>
    public static IReadOnlyList<float> Specials { get; } = BuildSpecials();

    /// <summary>
    /// Returns every 24 m line along one axis, in every block frame: for each block byte 0..254 the lines 24·k for
    /// k = −8..16 (the block's own 9 lines and the same world lines as the west/south and east/north neighbours
    /// express them), each at −4..+4 ULP. The other coordinate is 100.5 m; the other block byte and the low word vary.
    /// </summary>
    /// <param name="alongX">True for lines x = const, false for y = const.</param>
    /// <returns>255 × 25 × 9 = 57,375 points.</returns>
    public static SweepPoint[] Lines(bool alongX)
    {
        var points = new List<SweepPoint>(255 * 25 * ((2 * MaxUlps) + 1));
        ushort[] lows = [1, 64, LandDefs.BlockCellId, LandDefs.FirstEnvCellId, 37];
        for (int b = 0; b <= LandDefs.MaxBlockByte; b++)
        {
            for (int k = -8; k <= 16; k++)
            {
                var cell = alongX
                    ? new CellId((byte)b, (byte)(((b * 37) + 11) % 255), lows[(k + 8) % lows.Length])
                    : new CellId((byte)(((b * 37) + 11) % 255), (byte)b, lows[(k + 8) % lows.Length]);
                for (int u = -MaxUlps; u <= MaxUlps; u++)
                {
                    float v = Ulps.Step(24f * k, u);
                    points.Add(alongX ? new SweepPoint(cell, v, 100.5f) : new SweepPoint(cell, 100.5f, v));
                }
            }
        }

        return [.. points];
    }

    /// <summary>
    /// Returns the points where a disc's edge touches a 24 m line, 24·k ± r for every finite radius r &lt; 24 of
    /// <see cref="Radii"/> and k = 0..8, each at −4..+4 ULP, along x, in every 8th block frame: where retail's
    /// float32 24 − r decides the neighbour test (facts §3.2).
    /// </summary>
    /// <returns>The points.</returns>
    public static SweepPoint[] DiscEdges()
    {
        var points = new List<SweepPoint>();
        for (int b = 0; b <= LandDefs.MaxBlockByte; b += 8)
        {
            var cell = new CellId((byte)b, (byte)(255 - b - 1), 1);
            for (int k = 0; k <= 8; k++)
            {
                foreach (float r in Radii.Where(r => r < LandDefs.CellLength))
                {
                    foreach (float edge in (ReadOnlySpan<float>)[(24f * k) - r, (24f * k) + r])
                    {
                        for (int u = -MaxUlps; u <= MaxUlps; u++)
                        {
                            points.Add(new SweepPoint(cell, Ulps.Step(edge, u), 100.5f));
                        }
                    }
                }
            }
        }

        return [.. points];
    }

    /// <summary>
    /// Returns the block corners (0 or 192 on both axes, each at −4..+4 ULP) of every block on the map's diagonal
    /// bx = by, the four map-corner blocks, and every 16th block along the map's four edges (CI cost: ~100k points).
    /// </summary>
    /// <returns>The points.</returns>
    public static SweepPoint[] Corners()
    {
        var blocks = new HashSet<(int, int)>();
        for (int b = 0; b <= LandDefs.MaxBlockByte; b++)
        {
            blocks.Add((b, b));
            if (b % 16 == 0 || b == LandDefs.MaxBlockByte)
            {
                blocks.Add((b, 0));
                blocks.Add((b, LandDefs.MaxBlockByte));
                blocks.Add((0, b));
                blocks.Add((LandDefs.MaxBlockByte, b));
            }
        }

        var offsets = new List<float>();
        foreach (float line in (ReadOnlySpan<float>)[0f, LandDefs.BlockLength])
        {
            for (int u = -MaxUlps; u <= MaxUlps; u++)
            {
                offsets.Add(Ulps.Step(line, u));
            }
        }

        var points = new List<SweepPoint>(blocks.Count * offsets.Count * offsets.Count);
        foreach (var (bx, by) in blocks.Order())
        {
            var cell = new CellId((byte)bx, (byte)by, 1);
            foreach (float x in offsets)
            {
                foreach (float y in offsets)
                {
                    points.Add(new SweepPoint(cell, x, y));
                }
            }
        }

        return [.. points];
    }

    /// <summary>
    /// Returns every pair of special values (x, y) in the frames of the map's corner and edge blocks (0x00, 0x7F, 0xFE
    /// on each axis) and of ids with a 0xFF block byte, with land, block and env low words.
    /// </summary>
    /// <returns>The points.</returns>
    public static SweepPoint[] SpecialValues()
    {
        var points = new List<SweepPoint>();
        int[] bytes = [0x00, 0x7F, 0xFE, 0xFF];
        ushort[] lows = [1, 64, LandDefs.BlockCellId, LandDefs.FirstEnvCellId];
        foreach (int bx in bytes)
        {
            foreach (int by in bytes)
            {
                var cell = new CellId((byte)bx, (byte)by, lows[(bx + by) % lows.Length]);
                foreach (float x in Specials)
                {
                    foreach (float y in Specials)
                    {
                        points.Add(new SweepPoint(cell, x, y));
                    }
                }
            }
        }

        return [.. points];
    }

    private static float[] BuildSpecials()
    {
        float eps = LandDefs.Epsilon;
        var values = new List<float>
        {
            0f, float.Epsilon, 2 * float.Epsilon, MathF.BitDecrement(1.17549435E-38f), 1.17549435E-38f,
            eps, MathF.BitDecrement(eps), MathF.BitIncrement(eps), Ulps.Step(eps, -4), Ulps.Step(eps, 4),
            1e6f, MathF.BitIncrement(1e6f), float.MaxValue, float.PositiveInfinity, float.NaN,
            12f, 23.999998f, 24f, 191.99998f, 192f, 48960f, MathF.BitDecrement(48960f),
        };
        return [.. values, .. values.Select(v => -v)];
    }
}
