namespace AcPhys.Core;

/// <summary>The double-precision reference of the LandDefs cell math (<see cref="OutdoorPrecision.Double"/>); named apart from the float32 functions so no call (or reflection lookup) picks one for the other.</summary>
public static partial class LandDefs
{
    /// <summary>Returns the lcoord of the 24 m column containing a block-frame point given in double: as the float32 overload, floor toward −∞.</summary>
    /// <param name="id">An id whose low word is in range.</param>
    /// <param name="x">Block-frame x.</param>
    /// <param name="y">Block-frame y.</param>
    /// <param name="lcoord">The lcoord, or (0, 0) on failure.</param>
    /// <returns>False for an out-of-range low word, a 0xFF block byte, a non-finite coordinate, or a result off the map.</returns>
    public static bool GetOutsideLcoordInDouble(CellId id, double x, double y, out Lcoord lcoord)
    {
        lcoord = default;
        if (!CellInRange(id.Low) || !BlockIdToLcoord(id, out var block))
        {
            return false;
        }

        double gx = block.X + Math.Floor(x / CellLength);
        double gy = block.Y + Math.Floor(y / CellLength);
        if (!(gx >= 0 && gx < LandLength && gy >= 0 && gy < LandLength))
        {
            return false;
        }

        lcoord = new Lcoord((int)gx, (int)gy);
        return true;
    }

    /// <summary>
    /// Re-seats (id, x, y) as <see cref="AdjustToOutside(ref CellId, ref float, ref float)"/> does, but keeps the
    /// re-based point in double, where v − 192·⌊v/192⌋ is exact for any float32 v (no tie band, docs/numerics.md §7).
    /// </summary>
    /// <param name="id">Any id; on success a land cell id, on failure <see cref="CellId.None"/>.</param>
    /// <param name="x">Block-frame x; |x| &lt; EPS snaps to 0; on success re-based into [0, 192).</param>
    /// <param name="y">Block-frame y; as x.</param>
    /// <returns>As the float32 overload.</returns>
    public static bool AdjustToOutsideInDouble(ref CellId id, ref double x, ref double y)
    {
        if (!CellInRange(id.Low))
        {
            id = CellId.None;
            return false;
        }

        if (Math.Abs(x) < Epsilon)
        {
            x = 0;
        }

        if (Math.Abs(y) < Epsilon)
        {
            y = 0;
        }

        if (!GetOutsideLcoordInDouble(id, x, y, out var lcoord))
        {
            id = CellId.None;
            return false;
        }

        id = LcoordToGid(lcoord);
        x -= BlockLength * Math.Floor(x / BlockLength);
        y -= BlockLength * Math.Floor(y / BlockLength);
        return true;
    }
}
