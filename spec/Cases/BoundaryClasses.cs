using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// Names the boundary classes a case belongs to, so runs can show that boundaries are really hit
/// (exact 24 m and 192 m lines, their float32 neighbours, the EPS snap band, map edges, non-finite values, ...).
/// </summary>
public static class BoundaryClasses
{
    /// <summary>Every coordinate class, most specific first.</summary>
    public static readonly IReadOnlyList<string> CoordinateClasses =
    [
        "nonfinite", "huge", "neg-zero", "subnormal", "eps-band", "eps-edge", "line-192", "line-24", "ulp-near-line",
        "negative", "far", "interior",
    ];

    /// <summary>Every cell-id class.</summary>
    public static readonly IReadOnlyList<string> CellClasses =
    [
        "cell:zero", "cell:byte-FF", "cell:invalid-low", "cell:block", "cell:env", "cell:edge-block", "cell:high-byte", "cell:land",
    ];

    /// <summary>Every lcoord class.</summary>
    public static readonly IReadOnlyList<string> LcoordClasses = ["lcoord:off-map", "lcoord:edge", "lcoord:interior"];

    /// <summary>Returns the class of one block-frame coordinate.</summary>
    /// <param name="v">The coordinate.</param>
    /// <returns>One of <see cref="CoordinateClasses"/>.</returns>
    public static string OfCoordinate(float v)
    {
        if (!float.IsFinite(v))
        {
            return "nonfinite";
        }

        double a = Math.Abs((double)v);
        if (a > 1e6)
        {
            return "huge";
        }

        if (v == 0 && float.IsNegative(v))
        {
            return "neg-zero";
        }

        if (float.IsSubnormal(v))
        {
            return "subnormal";
        }

        if (a < LandDefs.Epsilon && v != 0)
        {
            return "eps-band";
        }

        if (Math.Abs(a - LandDefs.Epsilon) <= 4 * Ulp(LandDefs.Epsilon))
        {
            return "eps-edge";
        }

        double r24 = Math.IEEERemainder(v, 24.0);
        if (r24 == 0)
        {
            return Math.IEEERemainder(v, 192.0) == 0 ? "line-192" : "line-24";
        }

        if (Math.Abs(r24) <= 4 * Ulp(v))
        {
            return "ulp-near-line";
        }

        if (v < 0)
        {
            return "negative";
        }

        return v >= 192 ? "far" : "interior";
    }

    /// <summary>Returns the class of a cell id.</summary>
    /// <param name="id">The id.</param>
    /// <returns>One of <see cref="CellClasses"/>.</returns>
    public static string OfCell(CellId id)
    {
        if (id.IsNone)
        {
            return "cell:zero";
        }

        if (id.BlockX == 0xFF || id.BlockY == 0xFF)
        {
            return "cell:byte-FF";
        }

        if (!LandDefs.CellInRange(id.Low))
        {
            return "cell:invalid-low";
        }

        if (id.IsBlock)
        {
            return "cell:block";
        }

        if (id.IsEnv)
        {
            return "cell:env";
        }

        if (id.BlockX is 0 or 0xFE || id.BlockY is 0 or 0xFE)
        {
            return "cell:edge-block";
        }

        return id.BlockX >= 0x80 || id.BlockY >= 0x80 ? "cell:high-byte" : "cell:land";
    }

    /// <summary>Returns the class of an lcoord.</summary>
    /// <param name="lcoord">The lcoord.</param>
    /// <returns>One of <see cref="LcoordClasses"/>.</returns>
    public static string OfLcoord(Lcoord lcoord)
    {
        if (!lcoord.IsOnMap)
        {
            return "lcoord:off-map";
        }

        return lcoord.X is 0 or LandDefs.LandLength - 1 || lcoord.Y is 0 or LandDefs.LandLength - 1 ? "lcoord:edge" : "lcoord:interior";
    }

    /// <summary>Returns every class tag of a case: x and y as <c>coord:…</c>, the cell and the lcoord.</summary>
    /// <param name="c">The case.</param>
    /// <returns>The distinct tags.</returns>
    public static IEnumerable<string> Of(LandCase c)
    {
        string x = "coord:" + OfCoordinate(c.X);
        string y = "coord:" + OfCoordinate(c.Y);
        yield return x;
        if (y != x)
        {
            yield return y;
        }

        yield return OfCell(c.Cell);
        yield return OfLcoord(c.Lcoord);
    }

    /// <summary>Returns the most boundary-like coordinate class of a case, for a one-label distribution.</summary>
    /// <param name="c">The case.</param>
    /// <returns>The primary coordinate class.</returns>
    public static string PrimaryCoordinate(LandCase c)
    {
        string x = OfCoordinate(c.X), y = OfCoordinate(c.Y);
        int ix = IndexOf(x), iy = IndexOf(y);
        return ix <= iy ? x : y;
    }

    private static int IndexOf(string cls)
    {
        for (int i = 0; i < CoordinateClasses.Count; i++)
        {
            if (CoordinateClasses[i] == cls)
            {
                return i;
            }
        }

        return CoordinateClasses.Count;
    }

    private static double Ulp(double v) => Math.Abs(MathF.BitIncrement((float)Math.Abs(v)) - (float)Math.Abs(v));
}
