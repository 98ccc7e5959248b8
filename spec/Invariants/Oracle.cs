using AcPhys.Core;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// Independent ground truth for the invariants, computed from the facts (§1–§2) in plain integer and double
/// arithmetic, deliberately not through core: division and modulo instead of shifts and masks, floor in double.
/// </summary>
public static class Oracle
{
    /// <summary>Cells per map side.</summary>
    public const int MapCells = 2040;

    /// <summary>Tests a low word against facts §1.1: block 0xFFFF, land 1..64, env 0x100..0xFFFD.</summary>
    /// <param name="low">The low word.</param>
    /// <returns>True when valid.</returns>
    public static bool LowInRange(int low) => low == 0xFFFF || (low >= 1 && low <= 64) || (low >= 256 && low <= 65533);

    /// <summary>Tests whether both block bytes are on the map (8·byte &lt; 2040).</summary>
    /// <param name="id">The id.</param>
    /// <returns>True when on the map.</returns>
    public static bool BlockOnMap(CellId id) => (id.Value / 16777216u) * 8 < MapCells && (id.Value / 65536u % 256u) * 8 < MapCells;

    /// <summary>Tests whether an id is a land cell on the map.</summary>
    /// <param name="id">The id.</param>
    /// <returns>True for low word 1..64 with both block bytes 0x00..0xFE.</returns>
    public static bool IsLandCellOnMap(CellId id)
    {
        int low = (int)(id.Value % 65536u);
        return low >= 1 && low <= 64 && BlockOnMap(id);
    }

    /// <summary>Returns the global lcoord of a land cell id (x major: idx = low − 1, cx = idx / 8, cy = idx % 8).</summary>
    /// <param name="id">A land cell id.</param>
    /// <returns>(gx, gy).</returns>
    public static (int X, int Y) LcoordOf(CellId id)
    {
        int idx = (int)(id.Value % 65536u) - 1;
        return (((int)(id.Value / 16777216u) * 8) + (idx / 8), ((int)(id.Value / 65536u % 256u) * 8) + (idx % 8));
    }

    /// <summary>Returns the land cell id of an on-map lcoord.</summary>
    /// <param name="x">Column 0..2039.</param>
    /// <param name="y">Row 0..2039.</param>
    /// <returns>The id.</returns>
    public static CellId CellOf(int x, int y) => new((uint)(x / 8) * 16777216u + (uint)(y / 8) * 65536u + (uint)(1 + (8 * (x % 8)) + (y % 8)));

    /// <summary>Tests whether (x, y) lies on the map.</summary>
    /// <param name="x">Column.</param>
    /// <param name="y">Row.</param>
    /// <returns>True when both are in [0, 2040).</returns>
    public static bool OnMap(long x, long y) => x >= 0 && x < MapCells && y >= 0 && y < MapCells;

    /// <summary>
    /// The 24 m column containing a block-frame point, as get_outside_lcoord must answer it: floor in double,
    /// failure for a bad low word, an off-map block, a non-finite coordinate, or a column off the map.
    /// </summary>
    /// <param name="id">The id naming the block.</param>
    /// <param name="x">Block-frame x.</param>
    /// <param name="y">Block-frame y.</param>
    /// <returns>Success and the lcoord.</returns>
    public static (bool Ok, int X, int Y) Column(CellId id, float x, float y)
    {
        if (!LowInRange((int)(id.Value % 65536u)) || !BlockOnMap(id) || !double.IsFinite(x) || !double.IsFinite(y))
        {
            return (false, 0, 0);
        }

        double gx = (id.Value / 16777216u * 8) + Math.Floor(x / 24.0);
        double gy = (id.Value / 65536u % 256u * 8) + Math.Floor(y / 24.0);
        if (!(gx >= 0 && gx < MapCells && gy >= 0 && gy < MapCells))
        {
            return (false, 0, 0);
        }

        return (true, (int)gx, (int)gy);
    }

    /// <summary>Applies the AdjustToOutside snap: a coordinate strictly inside (−EPS, EPS) becomes +0 (facts §2.1 step 2).</summary>
    /// <param name="v">The coordinate.</param>
    /// <returns>The snapped coordinate.</returns>
    public static float Snap(float v) => Math.Abs((double)v) < 0.0002f ? 0f : v;

    /// <summary>
    /// Tests whether AdjustToOutside's re-base v − 192·⌊v/192⌋ is exact in float32. When it is not, the rounding can
    /// land the point on (or across) a 24 m line: the float32 tie band of docs/numerics.md.
    /// </summary>
    /// <param name="v">A block-frame coordinate.</param>
    /// <returns>True when the re-based value is representable exactly.</returns>
    public static bool RebaseIsExact(float v)
    {
        if (!float.IsFinite(v))
        {
            return false;
        }

        double exact = Snap(v) - (192.0 * Math.Floor(Snap(v) / 192.0));
        return (double)(float)exact == exact;
    }
}
