namespace AcPhys.Formats.Capture;

/// <summary>
/// A position as a log printed it: each coordinate's value (the decimal text read exactly as a double) and how many
/// decimals were printed, so a checker knows how far the true position may lie from the printed one.
/// </summary>
/// <param name="X">x, metres.</param>
/// <param name="Y">y, metres.</param>
/// <param name="Z">z, metres.</param>
/// <param name="DecimalsX">Decimals printed for x (0 to <see cref="MaxDecimals"/>).</param>
/// <param name="DecimalsY">Decimals printed for y.</param>
/// <param name="DecimalsZ">Decimals printed for z.</param>
internal readonly record struct PrintedPoint(double X, double Y, double Z, byte DecimalsX, byte DecimalsY, byte DecimalsZ)
{
    /// <summary>The most decimals a coordinate may carry (beyond it a float32 position has no more digits to print).</summary>
    public const int MaxDecimals = 12;

    private static readonly double[] Halves = [.. Enumerable.Range(0, MaxDecimals + 1).Select(d => 0.5 * Math.Pow(10, -d))];

    /// <summary>Gets half a unit of x's last printed digit: the true x lies within ± this of <see cref="X"/>.</summary>
    public double HalfX => Halves[DecimalsX];

    /// <summary>Gets half a unit of y's last printed digit.</summary>
    public double HalfY => Halves[DecimalsY];

    /// <summary>Returns half a unit of the last digit for a number of decimals.</summary>
    /// <param name="decimals">Decimals printed.</param>
    /// <returns>0.5 · 10^−decimals.</returns>
    public static double Half(int decimals) => Halves[decimals];

    /// <summary>Returns the point moved by whole metres (a frame change: exact in double for the offsets of the map).</summary>
    /// <param name="dx">Metres east.</param>
    /// <param name="dy">Metres north.</param>
    /// <returns>The moved point, same precision.</returns>
    public PrintedPoint Offset(double dx, double dy) => this with { X = X + dx, Y = Y + dy };
}
