using AcPhys.Core;

namespace ExamplePort;

/// <summary>The LandDefs functions (facts §1–§2): ids, the global 2040 × 2040 land-cell grid, and the 24 m columns.</summary>
/// <param name="bug">The seeded bug, if any.</param>
public sealed class Grid(Bug bug)
{
    /// <summary>Land cells along each side of the map.</summary>
    public const int Side = 2040;

    /// <summary>A land cell's side, metres.</summary>
    public const double Cell = 24.0;

    /// <summary>A landblock's side, metres.</summary>
    public const double Block = 192.0;

    private const float Snap = 0.0002f;

    /// <summary>Returns whether a global lcoord is on the map.</summary>
    /// <param name="x">Column.</param>
    /// <param name="y">Row.</param>
    /// <returns>0 ≤ x, y &lt; 2040.</returns>
    public bool OnMap(long x, long y) => bug == Bug.EdgeOffByOne
        ? x >= 0 && y >= 0 && x <= Side && y <= Side
        : x >= 0 && y >= 0 && x < Side && y < Side;

    /// <summary>Returns whether a low word names a cell at all: land 1..64, env 0x100..0xFFFD, or the block 0xFFFF.</summary>
    /// <param name="low">The low word.</param>
    /// <returns>Validity.</returns>
    public static bool LowInRange(int low) => low is (>= 1 and <= 64) or (>= 0x100 and <= 0xFFFD) or 0xFFFF;

    /// <summary>Returns the id's block origin lcoord (8·bx, 8·by), or null when off the map or id 0 (retail).</summary>
    /// <param name="id">Any id.</param>
    /// <returns>The lcoord.</returns>
    public Lcoord? BlockOrigin(CellId id)
    {
        int x = 8 * (int)(id.Value >> 24), y = 8 * (int)((id.Value >> 16) & 0xFF);
        return id.Value != 0 && OnMap(x, y) ? new Lcoord(x, y) : null;
    }

    /// <summary>Returns whether an id is valid: a low word in range, and both block bytes on the map (retail).</summary>
    /// <param name="id">Any id.</param>
    /// <returns>Validity.</returns>
    public bool InboundValid(CellId id) =>
        LowInRange((int)(id.Value & 0xFFFF)) && OnMap(8 * (int)(id.Value >> 24), bug == Bug.InboundXOnly ? 0 : 8 * (int)((id.Value >> 16) & 0xFF));

    /// <summary>Returns the global lcoord of a land cell id, or null (env cells and block ids too).</summary>
    /// <param name="id">Any id.</param>
    /// <returns>The lcoord.</returns>
    public Lcoord? CellLcoord(CellId id)
    {
        int low = (int)(id.Value & 0xFFFF);
        if (!InboundValid(id) || low >= 0x100 || BlockOrigin(id) is not Lcoord block)
        {
            return null;
        }

        // X is the major index of the low word (facts §1.2).
        int x = block.X + ((low - 1) / 8), y = block.Y + ((low - 1) % 8);
        return OnMap(x, y) ? new Lcoord(x, y) : null;
    }

    /// <summary>Returns the land cell id of a global lcoord, or id 0 off the map.</summary>
    /// <param name="x">Column.</param>
    /// <param name="y">Row.</param>
    /// <returns>The id.</returns>
    public CellId CellAt(long x, long y) => !OnMap(x, y)
        ? default
        : new CellId((uint)(x / 8) << 24 | (uint)(y / 8) << 16 | (uint)(1 + (8 * (x % 8)) + (y % 8)));

    /// <summary>Returns the lcoord of the 24 m column under a point of the id's block frame, or null.</summary>
    /// <param name="id">An id whose low word is in range; only its block counts.</param>
    /// <param name="x">Block-frame x, metres.</param>
    /// <param name="y">Block-frame y, metres.</param>
    /// <returns>The lcoord.</returns>
    public Lcoord? ColumnUnder(CellId id, float x, float y)
    {
        if (!LowInRange((int)(id.Value & 0xFFFF)) || BlockOrigin(id) is not Lcoord block)
        {
            return null;
        }

        double cx = block.X + Column(x / Cell), cy = block.Y + Column(y / Cell);
        return cx >= long.MinValue && cx <= long.MaxValue && cy >= long.MinValue && cy <= long.MaxValue && OnMap((long)cx, (long)cy)
            ? new Lcoord((int)cx, (int)cy)
            : null; // NaN fails the range test
    }

    /// <summary>Re-seats a point to the land cell under it, in that cell's block frame (facts §2.1).</summary>
    /// <param name="id">Any id.</param>
    /// <param name="x">Block-frame x.</param>
    /// <param name="y">Block-frame y.</param>
    /// <returns>Success, the land cell (0 on failure) and the point (snapped; re-based on success).</returns>
    public (bool Ok, CellId Cell, float X, float Y) Reseat(CellId id, float x, float y)
    {
        if (!LowInRange((int)(id.Value & 0xFFFF)))
        {
            return (false, default, x, y);
        }

        x = MathF.Abs(x) < Snap ? 0f : x; // strict, each axis alone
        y = MathF.Abs(y) < Snap ? 0f : y;
        return ColumnUnder(id, x, y) is Lcoord lc
            ? (true, CellAt(lc.X, lc.Y), (float)(x - (Block * Math.Floor(x / Block))), (float)(y - (Block * Math.Floor(y / Block))))
            : (false, default, x, y);
    }

    // Floor, never truncation: −0.5 m is the previous column (facts §2, get_outside_lcoord).
    private double Column(double q) => bug == Bug.Trunc ? Math.Truncate(q) : Math.Floor(q);
}
