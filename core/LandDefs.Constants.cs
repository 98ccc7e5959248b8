namespace AcPhys.Core;

/// <summary>Retail landscape definitions: the constants of facts §1.1 and the cell math of facts §2.</summary>
public static partial class LandDefs
{
    /// <summary>Low word of a block id (the landblock itself).</summary>
    public const ushort BlockCellId = 0xFFFF;

    /// <summary>First env (indoor) low word.</summary>
    public const ushort FirstEnvCellId = 0x100;

    /// <summary>Last env (indoor) low word.</summary>
    public const ushort LastEnvCellId = 0xFFFD;

    /// <summary>First land (outdoor) low word.</summary>
    public const ushort FirstLandCellId = 1;

    /// <summary>Last land (outdoor) low word.</summary>
    public const ushort LastLandCellId = 64;

    /// <summary>Mask of the landblock part of a cell id.</summary>
    public const uint BlockMask = 0xFFFF0000;

    /// <summary>Mask of the low word of a cell id.</summary>
    public const uint CellIdMask = 0x0000FFFF;

    /// <summary>Mask of the in-block part of an lcoord (cells per block side − 1).</summary>
    public const int LandblockMask = 7;

    /// <summary>Shift from a block byte to its first lcoord (8 cells per block side).</summary>
    public const int LandblockShift = 3;

    /// <summary>Cells per landblock side.</summary>
    public const int BlockSide = 8;

    /// <summary>Lcoords per map side: valid lcoords are 0..2039.</summary>
    public const int LandLength = 2040;

    /// <summary>Largest valid block byte (0xFE); 0xFF gives lcoord 2040 and is never valid.</summary>
    public const int MaxBlockByte = 0xFE;

    /// <summary>Side of a land cell, metres.</summary>
    public const float CellLength = 24f;

    /// <summary>Side of a landblock, metres.</summary>
    public const float BlockLength = 192f;

    /// <summary>Half the side of a land cell, metres.</summary>
    public const float HalfSquareLength = 12f;

    /// <summary>PhysicsGlobals.EPSILON, metres: the AdjustToOutside snap band and portal-plane padding (facts §0, §1.5).</summary>
    public const float Epsilon = 0.0002f;
}
