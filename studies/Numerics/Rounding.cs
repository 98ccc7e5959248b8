using AcPhys.Core;
using AcPhys.Spec.Invariants;
using AcPhys.Studies.Invariants;

namespace AcPhys.Studies.Numerics;

/// <summary>
/// Names the float32 roundings of retail's outdoor math that a query actually meets: the places where the float32
/// mode may part from exact arithmetic (docs/numerics.md). Computed from the case alone, independently of any answer.
/// </summary>
public static class Rounding
{
    /// <summary>AdjustToOutside's re-base v − 192·⌊v/192⌋ is not representable (negative v far from a line, facts §2.1 step 4).</summary>
    public const string Rebase = "rebase";

    /// <summary>The in-cell point lies between retail's float32 24 − r and the exact 24 − r (facts §3.2 maxRad).</summary>
    public const string MaxRad = "max-rad";

    /// <summary>The pick re-expresses sphere 0's centre in a neighbouring block's frame and float32 rounds it (facts §4 step 4b).</summary>
    public const string Reframe = "reframe";

    /// <summary>Returns the roundings a query meets, in the order above (spheres up to the first off the map).</summary>
    /// <param name="c">The query.</param>
    /// <returns>The distinct rounding names; empty when every float32 step of the query is exact.</returns>
    public static IReadOnlyList<string> Of(AcPhys.Formats.Cases.OutdoorCase c)
    {
        var found = new List<string>(3);
        foreach (var s in c.Spheres)
        {
            if (ExactOutdoor.Column(c.Cell, s.Center.X, s.Center.Y) is not var (_, _, px, py))
            {
                break;
            }

            if (!Oracle.RebaseIsExact(s.Center.X) || !Oracle.RebaseIsExact(s.Center.Y))
            {
                AddOnce(found, Rebase);
            }

            if (float.IsFinite(s.Radius) && (InMaxRadBand(px, s.Radius) || InMaxRadBand(py, s.Radius)))
            {
                AddOnce(found, MaxRad);
            }
        }

        if (c.Spheres.Count > 0 && ReframeRounds(c.Spheres[0].Center.X) | ReframeRounds(c.Spheres[0].Center.Y))
        {
            AddOnce(found, Reframe);
        }

        return found;
    }

    /// <summary>Tests whether the exact in-cell coordinate lies between retail's float32 24 − r and the exact 24 − r, both ends included.</summary>
    /// <param name="p">Exact in-cell coordinate.</param>
    /// <param name="r">The radius.</param>
    /// <returns>True when the float32 strict test p &gt; 24 − r may answer differently from the exact one.</returns>
    public static bool InMaxRadBand(Dyadic p, float r)
    {
        var exact = Dyadic.Of(24) - Dyadic.Of(r);
        float rounded = LandDefs.CellLength - r;
        if (!float.IsFinite(rounded))
        {
            return false;
        }

        var f = Dyadic.Of(rounded);
        var (lo, hi) = f < exact ? (f, exact) : (exact, f);
        return f != exact && p >= lo && p <= hi;
    }

    // v ± 192 (a candidate in a neighbouring block's frame) is not representable in float32 (Dyadic: exact even for subnormal v).
    private static bool ReframeRounds(float v)
    {
        if (!float.IsFinite(v))
        {
            return false;
        }

        foreach (float shift in (ReadOnlySpan<float>)[LandDefs.BlockLength, -LandDefs.BlockLength])
        {
            if (Dyadic.Of(v + shift) != Dyadic.Of(v) + Dyadic.Of(shift))
            {
                return true;
            }
        }

        return false;
    }

    private static void AddOnce(List<string> list, string name)
    {
        if (!list.Contains(name))
        {
            list.Add(name);
        }
    }
}
