using System.Numerics;

namespace AcPhys.Core;

/// <summary>The LandDefs functions of facts §2, with retail semantics where ACE differs (facts §7 #15, #16).</summary>
/// <remarks>
/// Every function is pure, allocation-free and total: any input (any id, NaN, ±Infinity, ±float.MaxValue)
/// returns a failure value instead of throwing, and never a valid-looking cell for a non-finite coordinate.
/// </remarks>
public static partial class LandDefs
{
    /// <summary>Tests whether (x, y) is a map lcoord: 0 ≤ x, y &lt; 2040 (retail <c>in_bounds</c>).</summary>
    /// <param name="x">Global cell column.</param>
    /// <param name="y">Global cell row.</param>
    /// <returns>True when both lie in [0, 2040).</returns>
    public static bool InBounds(int x, int y) => (uint)x < LandLength && (uint)y < LandLength;

    /// <summary>Tests a low word: 0xFFFF, 1..64 or 0x100..0xFFFD (<c>cell_in_range</c>).</summary>
    /// <param name="low">The low word of an id.</param>
    /// <returns>True for a block, land or env low word.</returns>
    public static bool CellInRange(ushort low) =>
        low == BlockCellId
        || low is >= FirstLandCellId and <= LastLandCellId
        || low is >= FirstEnvCellId and <= LastEnvCellId;

    /// <summary>Returns the lcoord of the south-west cell of the id's landblock: (8·bx, 8·by). The low word is ignored.</summary>
    /// <param name="id">Any id.</param>
    /// <param name="lcoord">The block's first lcoord, or (0, 0) on failure.</param>
    /// <returns>False when either block byte is 0xFF, and (retail, facts §7 #16) for id 0.</returns>
    public static bool BlockIdToLcoord(CellId id, out Lcoord lcoord)
    {
        lcoord = default;
        if (id.IsNone)
        {
            return false;
        }

        int x = id.BlockX << LandblockShift;
        int y = id.BlockY << LandblockShift;
        if (x >= LandLength || y >= LandLength)
        {
            return false;
        }

        lcoord = new Lcoord(x, y);
        return true;
    }

    /// <summary>Tests <c>cell_in_range(low)</c> and that both block bytes are on the map (retail checks X and Y, facts §7 #15).</summary>
    /// <param name="id">Any id.</param>
    /// <returns>True for a well-formed id on the map.</returns>
    public static bool InboundValidCellId(CellId id) =>
        CellInRange(id.Low)
        && (id.BlockX << LandblockShift) < LandLength
        && (id.BlockY << LandblockShift) < LandLength;

    /// <summary>Returns the global lcoord of a land cell id: (8·bx + cx, 8·by + cy) (<c>gid_to_lcoord</c>).</summary>
    /// <param name="id">A land cell id.</param>
    /// <param name="lcoord">The lcoord, or (0, 0) on failure.</param>
    /// <returns>False for an invalid id and, as retail, for any low word ≥ 0x100 (env cells and 0xFFFF).</returns>
    public static bool GidToLcoord(CellId id, out Lcoord lcoord)
    {
        lcoord = default;
        if (!InboundValidCellId(id) || id.Low >= FirstEnvCellId)
        {
            return false;
        }

        int index = id.Low - 1;
        int x = (id.BlockX << LandblockShift) + (index >> LandblockShift);
        int y = (id.BlockY << LandblockShift) + (index & LandblockMask);
        if (!InBounds(x, y))
        {
            return false;
        }

        lcoord = new Lcoord(x, y);
        return true;
    }

    /// <summary>Returns the land cell id of an lcoord (<c>lcoord_to_gid</c>): block (x≫3, y≫3), low word 1 + 8·(x&amp;7) + (y&amp;7).</summary>
    /// <param name="x">Global cell column.</param>
    /// <param name="y">Global cell row.</param>
    /// <returns>The land cell id, or <see cref="CellId.None"/> when (x, y) is off the map.</returns>
    public static CellId LcoordToGid(int x, int y)
    {
        if (!InBounds(x, y))
        {
            return CellId.None;
        }

        return new CellId((byte)(x >> LandblockShift), (byte)(y >> LandblockShift), (ushort)(1 + ((x & LandblockMask) << LandblockShift) + (y & LandblockMask)));
    }

    /// <summary>Returns the land cell id of an lcoord.</summary>
    /// <param name="lcoord">The lcoord.</param>
    /// <returns>The land cell id, or <see cref="CellId.None"/> when off the map.</returns>
    public static CellId LcoordToGid(Lcoord lcoord) => LcoordToGid(lcoord.X, lcoord.Y);

    /// <summary>
    /// Returns the lcoord of the 24 m column containing a block-frame point (<c>get_outside_lcoord</c>):
    /// (8·bx + ⌊x/24⌋, 8·by + ⌊y/24⌋). Only the block part of the id matters.
    /// </summary>
    /// <param name="id">An id whose low word is in range (land, env or 0xFFFF).</param>
    /// <param name="x">Block-frame x, any sign or magnitude.</param>
    /// <param name="y">Block-frame y, any sign or magnitude.</param>
    /// <param name="lcoord">The lcoord, or (0, 0) on failure.</param>
    /// <returns>False for an out-of-range low word, a 0xFF block byte, a non-finite coordinate, or a result off the map.</returns>
    public static bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord)
    {
        lcoord = default;
        if (!CellInRange(id.Low) || !BlockIdToLcoord(id, out var block))
        {
            return false;
        }

        // Facts §2: floor toward −∞, not truncation (x = −0.5 is the previous cell). Dividing the float32 in
        // double is exact enough that the floor is the exact one. Range-test in double before converting:
        // since .NET 9 (int)NaN is 0 and huge values saturate, either of which would fake a valid cell.
        double gx = block.X + Math.Floor(x / (double)CellLength);
        double gy = block.Y + Math.Floor(y / (double)CellLength);
        if (!(gx >= 0 && gx < LandLength && gy >= 0 && gy < LandLength))
        {
            return false; // also catches NaN: every comparison with NaN is false
        }

        lcoord = new Lcoord((int)gx, (int)gy);
        return true;
    }

    /// <summary>
    /// Re-seats (id, x, y) to the land cell whose 24 m column contains the point (<c>AdjustToOutside</c>, facts §2.1).
    /// </summary>
    /// <param name="id">Any id; on success a land cell id, on failure <see cref="CellId.None"/>.</param>
    /// <param name="x">Block-frame x; |x| &lt; EPS snaps to 0; on success re-based into [0, 192).</param>
    /// <param name="y">Block-frame y; as x.</param>
    /// <returns>False when the low word is out of range (x, y untouched) or the column is off the map (x, y snapped).</returns>
    public static bool AdjustToOutside(ref CellId id, ref float x, ref float y)
    {
        if (!CellInRange(id.Low))
        {
            id = CellId.None;
            return false;
        }

        // Facts §2.1 step 2: strict |v| < EPS snaps, independently per axis; this keeps −0.0001 in its block.
        if (Math.Abs(x) < Epsilon)
        {
            x = 0f;
        }

        if (Math.Abs(y) < Epsilon)
        {
            y = 0f;
        }

        if (!GetOutsideLcoord(id, x, y, out var lcoord))
        {
            id = CellId.None;
            return false;
        }

        id = LcoordToGid(lcoord);
        x = Rebase(x);
        y = Rebase(y);
        return true;
    }

    /// <summary>Re-seats a position; z is never touched (facts §2.1).</summary>
    /// <param name="id">Any id; on success a land cell id, on failure <see cref="CellId.None"/>.</param>
    /// <param name="position">Block-frame point.</param>
    /// <returns>As <see cref="AdjustToOutside(ref CellId, ref float, ref float)"/>.</returns>
    public static bool AdjustToOutside(ref CellId id, ref Vector3 position)
    {
        float x = position.X, y = position.Y;
        bool ok = AdjustToOutside(ref id, ref x, ref y);
        position = new Vector3(x, y, position.Z);
        return ok;
    }

    /// <summary>
    /// Returns the offset from one id's block frame to another's: (0,0,0) for the same landblock, else
    /// 192·(Δbx, Δby, 0) (<c>GetBlockOffset</c>). As retail, nothing is validated: any byte, and id 0, count as given.
    /// </summary>
    /// <param name="from">The id whose frame points are expressed in.</param>
    /// <param name="to">The id whose frame is wanted.</param>
    /// <returns>The vector to subtract from a <paramref name="from"/>-frame point to express it in <paramref name="to"/>'s frame.</returns>
    public static Vector3 GetBlockOffset(CellId from, CellId to)
    {
        if ((from.Value & BlockMask) == (to.Value & BlockMask))
        {
            return Vector3.Zero;
        }

        return new Vector3(
            BlockLength * (to.BlockX - from.BlockX),
            BlockLength * (to.BlockY - from.BlockY),
            0f);
    }

    /// <summary>Tests whether a disc of radius r around a block-frame point lies inside the block (<c>InBlock</c>): lower bound inclusive, upper strict.</summary>
    /// <param name="position">Block-frame point.</param>
    /// <param name="radius">Radius, metres.</param>
    /// <returns>True when r ≤ x, y &lt; 192 − r.</returns>
    public static bool InBlock(Vector3 position, float radius)
    {
        if (position.X < radius || position.Y < radius)
        {
            return false;
        }

        return position.X < BlockLength - radius && position.Y < BlockLength - radius;
    }

    // v − 192·⌊v/192⌋, the floor taken in double (exact for float32 input). The difference is exact in double
    // and rounds once to float32, as the retail float subtraction does.
    private static float Rebase(float v) => (float)(v - (BlockLength * Math.Floor(v / (double)BlockLength)));
}
