using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Generators;

/// <summary>
/// Shrinks a failing LandDefs case toward one a person reads at a glance: coordinates toward 0, whole metres and
/// the nearest 24 m line; the cell toward low word 1 and block 0x0000; the lcoord toward (0, 0).
/// Every candidate differs bit-wise from its source (NaN included), so shrinking always terminates.
/// </summary>
public static class LandCaseShrinker
{
    /// <summary>Returns simpler candidates for a case, simplest first.</summary>
    /// <param name="c">The failing case.</param>
    /// <returns>Candidates.</returns>
    public static IEnumerable<LandCase> Shrink(LandCase c)
    {
        foreach (var x in Simpler(c.X))
        {
            yield return c with { X = x };
        }

        foreach (var y in Simpler(c.Y))
        {
            yield return c with { Y = y };
        }

        foreach (var cell in Simpler(c.Cell))
        {
            yield return c with { Cell = cell };
        }

        if (c.Lcoord.X != 0)
        {
            yield return c with { Lcoord = c.Lcoord with { X = c.Lcoord.X / 2 } };
        }

        if (c.Lcoord.Y != 0)
        {
            yield return c with { Lcoord = c.Lcoord with { Y = c.Lcoord.Y / 2 } };
        }
    }

    private static IEnumerable<float> Simpler(float v)
    {
        var seen = new HashSet<int> { BitConverter.SingleToInt32Bits(v) };
        foreach (var candidate in Candidates(v))
        {
            if (seen.Add(BitConverter.SingleToInt32Bits(candidate)))
            {
                yield return candidate;
            }
        }
    }

    private static IEnumerable<float> Candidates(float v)
    {
        yield return 0f;
        if (!float.IsFinite(v))
        {
            yield break;
        }

        yield return MathF.Round(v);
        yield return MathF.Round(v / 24f) * 24f;
        if (Math.Abs(v) > 1f)
        {
            yield return MathF.Truncate(v / 2f);
        }

        yield return MathF.Round(v * 1000f) / 1000f;
    }

    private static IEnumerable<CellId> Simpler(CellId id)
    {
        if (id.IsLand && id.Low != 1)
        {
            yield return id.WithLow(1);
        }

        if (id.BlockX != 0 && id.BlockX != 0xFF)
        {
            yield return new CellId((byte)(id.BlockX / 2), id.BlockY, id.Low);
        }

        if (id.BlockY != 0 && id.BlockY != 0xFF)
        {
            yield return new CellId(id.BlockX, (byte)(id.BlockY / 2), id.Low);
        }
    }
}
