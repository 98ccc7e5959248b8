using AcPhys.Core;
using AcPhys.Studies.Invariants;

namespace AcPhys.Studies.Numerics;

/// <summary>Re-base exactness over one binade of block-frame coordinates, enumerated whole.</summary>
/// <param name="Low">Lower end of |v|, metres.</param>
/// <param name="High">Upper end of |v| (exclusive), metres.</param>
/// <param name="Negative">True for v &lt; 0.</param>
/// <param name="Floats">Float32 values in the binade (that survive the EPS snap).</param>
/// <param name="Inexact">Values whose float32 re-base is not exact.</param>
/// <param name="OntoLine">Values whose re-base rounds onto the east/north line of the exact cell (the tie band: the float32 cell test then disagrees).</param>
public sealed record RebaseBinade(double Low, double High, bool Negative, long Floats, long Inexact, long OntoLine);

/// <summary>The width of the tie band below one 24 m line, seen from the neighbouring block's frame.</summary>
/// <param name="Line">The line in the target block, metres (24·j).</param>
/// <param name="Frame">The coordinate that names it in the east/north neighbour's frame (line − 192).</param>
/// <param name="Ulps">Consecutive float32 values just below <paramref name="Frame"/> that re-base onto the line.</param>
/// <param name="Metres">The band's width, metres.</param>
public sealed record LineTieBand(float Line, float Frame, int Ulps, double Metres);

/// <summary>How retail's float32 24 − r rounds for one radius.</summary>
/// <param name="Radius">r.</param>
/// <param name="Float32">float32 24 − r.</param>
/// <param name="ErrorMetres">float32 minus exact, metres.</param>
/// <param name="Flips">True when it rounds up below 24, so the one float32 in-cell point equal to it is tested wrongly.</param>
public sealed record MaxRadRounding(float Radius, float Float32, double ErrorMetres, bool Flips);

/// <summary>
/// Measures the float32 tie bands of the outdoor cell math by enumeration (docs/numerics.md tables): re-base exactness
/// per binade, the band width below each line, 24 − r per radius, the EPS snap band and the pick's re-framing band.
/// The exact values are computed in double, where they are exact for float32 input (cross-checked against the
/// rational oracle by the extreme sweeps).
/// </summary>
public static class TieBands
{
    /// <summary>Enumerates every float32 in the binades [2^k, 2^(k+1)) for k = −13..15 (EPS to beyond the map), both signs.</summary>
    /// <returns>One row per binade and sign.</returns>
    public static IReadOnlyList<RebaseBinade> RebaseByBinade()
    {
        var rows = new List<RebaseBinade>();
        for (int k = -13; k <= 15; k++)
        {
            foreach (bool negative in (ReadOnlySpan<bool>)[true, false])
            {
                float low = MathF.ScaleB(1f, k), high = MathF.ScaleB(1f, k + 1);
                int first = BitConverter.SingleToInt32Bits(low), last = BitConverter.SingleToInt32Bits(high);
                long floats = 0, inexact = 0, onto = 0;
                object gate = new();
                Parallel.For(first, last, () => (0L, 0L, 0L), (bits, _, t) =>
                {
                    float v = BitConverter.Int32BitsToSingle(bits);
                    v = negative ? -v : v;
                    if (Math.Abs(v) < LandDefs.Epsilon)
                    {
                        return t;
                    }

                    double exact = v - (192.0 * Math.Floor(v / 192.0));
                    float rounded = (float)exact;
                    bool isInexact = rounded != exact;
                    bool isOnto = isInexact && rounded == 24.0 * (Math.Floor(exact / 24.0) + 1);
                    return (t.Item1 + 1, t.Item2 + (isInexact ? 1 : 0), t.Item3 + (isOnto ? 1 : 0));
                },
                t =>
                {
                    lock (gate)
                    {
                        floats += t.Item1;
                        inexact += t.Item2;
                        onto += t.Item3;
                    }
                });
                rows.Add(new RebaseBinade(low, high, negative, floats, inexact, onto));
            }
        }

        return rows;
    }

    /// <summary>Scans down from each line 24·j − 192 (j = 0..8) and counts the float32 values that re-base onto the line.</summary>
    /// <returns>One row per line.</returns>
    public static IReadOnlyList<LineTieBand> BelowLines()
    {
        var rows = new List<LineTieBand>();
        for (int j = 0; j <= 8; j++)
        {
            float line = 24f * j, frame = line - LandDefs.BlockLength;
            float v = frame;
            int n = 0;
            while (true)
            {
                float below = MathF.BitDecrement(v);
                if (Math.Abs(below) < LandDefs.Epsilon)
                {
                    break; // snapped to 0 first (facts §2.1 step 2)
                }

                double exact = below - (192.0 * Math.Floor(below / 192.0));
                if ((float)exact != (j == 0 ? 192f : line))
                {
                    break;
                }

                v = below;
                n++;
            }

            rows.Add(new LineTieBand(line, frame, n, (double)frame - v));
        }

        return rows;
    }

    /// <summary>Rounds 24 − r in float32 for each radius.</summary>
    /// <param name="radii">The radii.</param>
    /// <returns>One row per radius.</returns>
    public static IReadOnlyList<MaxRadRounding> MaxRad(IEnumerable<float> radii) =>
        radii.Select(r =>
        {
            float f = LandDefs.CellLength - r;
            var error = Dyadic.Of(f) - (Dyadic.Of(24) - Dyadic.Of(r)); // exact even for a subnormal r
            return new MaxRadRounding(r, f, error.ToDouble(), error > default(Dyadic) && f < LandDefs.CellLength);
        }).ToList();

    /// <summary>Measures how often float32 24 − r rounds up, over every float32 radius in [2^-10, 24).</summary>
    /// <returns>(radii, rounding up, largest error in metres).</returns>
    public static (long Radii, long RoundsUp, double MaxError) MaxRadOverAllRadii()
    {
        int first = BitConverter.SingleToInt32Bits(MathF.ScaleB(1f, -10)), last = BitConverter.SingleToInt32Bits(24f);
        long total = 0, up = 0;
        double max = 0;
        object gate = new();
        Parallel.For(first, last, () => (0L, 0L, 0.0), (bits, _, t) =>
        {
            float r = BitConverter.Int32BitsToSingle(bits);
            double error = (double)(LandDefs.CellLength - r) - (24.0 - (double)r);
            return (t.Item1 + 1, t.Item2 + (error > 0 ? 1 : 0), Math.Max(t.Item3, Math.Abs(error)));
        },
        t =>
        {
            lock (gate)
            {
                total += t.Item1;
                up += t.Item2;
                max = Math.Max(max, t.Item3);
            }
        });
        return (total, up, max);
    }

    /// <summary>Returns the largest centre v &gt; 0 for which retail's re-framed v − 192 rounds to exactly −192, onto the western candidate's closed square.</summary>
    /// <returns>The band's upper end, metres.</returns>
    public static float ReframeBand()
    {
        // Binary search over the bit patterns of positive floats: the predicate holds up to half an ULP of 192.
        int lo = 1, hi = BitConverter.SingleToInt32Bits(1f);
        while (lo < hi)
        {
            int mid = lo + ((hi - lo + 1) / 2);
            if (BitConverter.Int32BitsToSingle(mid) - LandDefs.BlockLength == -LandDefs.BlockLength)
            {
                lo = mid;
            }
            else
            {
                hi = mid - 1;
            }
        }

        return BitConverter.Int32BitsToSingle(lo);
    }
}
