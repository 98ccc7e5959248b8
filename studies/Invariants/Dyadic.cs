using System.Numerics;

namespace AcPhys.Studies.Invariants;

/// <summary>
/// An exact rational with denominator 2¹⁴⁹ (the float32 subnormal step): every finite float32 and every integer is
/// one, and sums, differences, comparisons and floor division by an integer are exact. Slow (BigInteger); oracle use only.
/// </summary>
/// <param name="Units">The value in units of 2⁻¹⁴⁹.</param>
public readonly record struct Dyadic(BigInteger Units) : IComparable<Dyadic>
{
    private const int Shift = 149;

    /// <summary>Returns the exact value of a finite float32.</summary>
    /// <param name="v">The value (finite).</param>
    /// <returns>The dyadic.</returns>
    /// <exception cref="ArgumentOutOfRangeException">The value is NaN or infinite.</exception>
    public static Dyadic Of(float v)
    {
        if (!float.IsFinite(v))
        {
            throw new ArgumentOutOfRangeException(nameof(v), v, "not finite");
        }

        int bits = BitConverter.SingleToInt32Bits(v);
        int exponent = (bits >> 23) & 0xFF;
        int fraction = bits & 0x7FFFFF;
        BigInteger units = exponent == 0 ? fraction : new BigInteger(fraction | 0x800000) << (exponent - 1);
        return new Dyadic(bits < 0 ? -units : units);
    }

    /// <summary>Returns the exact value of an integer.</summary>
    /// <param name="v">The value.</param>
    /// <returns>The dyadic.</returns>
    public static Dyadic Of(long v) => new(new BigInteger(v) << Shift);

    /// <summary>Returns the sum.</summary>
    /// <param name="a">Left.</param>
    /// <param name="b">Right.</param>
    /// <returns>a + b, exact.</returns>
    public static Dyadic operator +(Dyadic a, Dyadic b) => new(a.Units + b.Units);

    /// <summary>Returns the difference.</summary>
    /// <param name="a">Left.</param>
    /// <param name="b">Right.</param>
    /// <returns>a − b, exact.</returns>
    public static Dyadic operator -(Dyadic a, Dyadic b) => new(a.Units - b.Units);

    /// <summary>Compares exactly.</summary>
    /// <param name="a">Left.</param>
    /// <param name="b">Right.</param>
    /// <returns>a &lt; b.</returns>
    public static bool operator <(Dyadic a, Dyadic b) => a.Units < b.Units;

    /// <summary>Compares exactly.</summary>
    /// <param name="a">Left.</param>
    /// <param name="b">Right.</param>
    /// <returns>a &gt; b.</returns>
    public static bool operator >(Dyadic a, Dyadic b) => a.Units > b.Units;

    /// <summary>Compares exactly.</summary>
    /// <param name="a">Left.</param>
    /// <param name="b">Right.</param>
    /// <returns>a ≤ b.</returns>
    public static bool operator <=(Dyadic a, Dyadic b) => a.Units <= b.Units;

    /// <summary>Compares exactly.</summary>
    /// <param name="a">Left.</param>
    /// <param name="b">Right.</param>
    /// <returns>a ≥ b.</returns>
    public static bool operator >=(Dyadic a, Dyadic b) => a.Units >= b.Units;

    /// <summary>Returns ⌊this / n⌋ for a positive integer n, toward −∞.</summary>
    /// <param name="n">The divisor (&gt; 0).</param>
    /// <returns>The floor.</returns>
    public BigInteger FloorDiv(long n)
    {
        var d = new BigInteger(n) << Shift;
        var q = BigInteger.DivRem(Units, d, out var rem);
        return rem.Sign < 0 ? q - 1 : q;
    }

    /// <summary>Returns the nearest double (for reports).</summary>
    /// <returns>The approximation.</returns>
    public double ToDouble() => (double)Units / Math.Pow(2, Shift);

    /// <inheritdoc/>
    public int CompareTo(Dyadic other) => Units.CompareTo(other.Units);
}
