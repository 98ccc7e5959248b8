namespace AcPhys.Core;

/// <summary>
/// Represents a global land-cell coordinate ("lcoord"): one square of the map-wide 2040 × 2040 grid of
/// 24 m land cells, <c>gx = 8·bx + cx</c>, <c>gy = 8·by + cy</c> (facts §1.3).
/// </summary>
/// <remarks>
/// Any pair of ints can be held, so that neighbours of edge cells (−1, 2040) can be expressed;
/// <see cref="IsOnMap"/> says whether it is a real cell. Block boundaries are not special in this grid.
/// </remarks>
/// <threadsafety>Immutable value type.</threadsafety>
public readonly record struct Lcoord(int X, int Y)
{
    /// <summary>Gets a value indicating whether both coordinates lie in [0, 2040) (retail <c>in_bounds</c>).</summary>
    public bool IsOnMap => LandDefs.InBounds(X, Y);

    /// <summary>Gets the lcoord of the south-west cell of this lcoord's landblock (low three bits cleared).</summary>
    public Lcoord BlockOrigin => new(X & ~LandDefs.LandblockMask, Y & ~LandDefs.LandblockMask);

    /// <summary>Returns this lcoord moved by (dx, dy) cells.</summary>
    /// <param name="dx">Cells east.</param>
    /// <param name="dy">Cells north.</param>
    /// <returns>The shifted lcoord (not range-checked).</returns>
    public Lcoord Offset(int dx, int dy) => new(X + dx, Y + dy);

    /// <summary>Formats the lcoord as <c>(x, y)</c>.</summary>
    /// <returns>The formatted lcoord.</returns>
    public override string ToString() => string.Create(System.Globalization.CultureInfo.InvariantCulture, $"({X}, {Y})");
}
