namespace AcPhys.Core;

/// <summary>Represents a landblock: the high word <c>0xXXYY</c> of a cell id (facts §1.1).</summary>
/// <threadsafety>Immutable value type.</threadsafety>
public readonly struct LandblockId : IEquatable<LandblockId>
{
    /// <summary>Initializes a landblock id from its 16-bit value <c>0xXXYY</c>.</summary>
    /// <param name="value">The high word of a cell id.</param>
    public LandblockId(ushort value) => Value = value;

    /// <summary>Initializes a landblock id from its column and row bytes.</summary>
    /// <param name="x">Column byte.</param>
    /// <param name="y">Row byte.</param>
    public LandblockId(byte x, byte y) => Value = (ushort)((x << 8) | y);

    /// <summary>Gets the 16-bit value <c>0xXXYY</c>.</summary>
    public ushort Value { get; }

    /// <summary>Gets the column byte.</summary>
    public byte X => (byte)(Value >> 8);

    /// <summary>Gets the row byte.</summary>
    public byte Y => (byte)Value;

    /// <summary>Gets a value indicating whether both bytes are on the map (0x00..0xFE); byte 0xFF never is (facts §1.3).</summary>
    public bool IsOnMap => X < LandDefs.MaxBlockByte + 1 && Y < LandDefs.MaxBlockByte + 1;

    /// <summary>Gets the block id <c>0xXXYYFFFF</c>.</summary>
    public CellId BlockCell => new(X, Y, LandDefs.BlockCellId);

    /// <summary>Returns the land cell id of this block at in-block cell (cx, cy).</summary>
    /// <param name="cx">Column within the block, 0..7.</param>
    /// <param name="cy">Row within the block, 0..7.</param>
    /// <returns>The id with low word <c>1 + 8·cx + cy</c> (facts §1.2).</returns>
    /// <exception cref="ArgumentOutOfRangeException">cx or cy is outside 0..7.</exception>
    public CellId LandCell(int cx, int cy)
    {
        Internal.Preconditions.CheckRange(cx, 0, LandDefs.BlockSide - 1, nameof(cx));
        Internal.Preconditions.CheckRange(cy, 0, LandDefs.BlockSide - 1, nameof(cy));
        return new CellId(X, Y, (ushort)(1 + (cx * LandDefs.BlockSide) + cy));
    }

    /// <summary>Formats the landblock as <c>0xXXYY</c>.</summary>
    /// <returns>The formatted id.</returns>
    public override string ToString() => "0x" + Value.ToString("X4", System.Globalization.CultureInfo.InvariantCulture);

    /// <inheritdoc/>
    public bool Equals(LandblockId other) => Value == other.Value;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is LandblockId other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => Value;

    /// <summary>Compares two landblocks for equality.</summary>
    /// <param name="left">The first block.</param>
    /// <param name="right">The second block.</param>
    /// <returns>True when equal.</returns>
    public static bool operator ==(LandblockId left, LandblockId right) => left.Equals(right);

    /// <summary>Compares two landblocks for inequality.</summary>
    /// <param name="left">The first block.</param>
    /// <param name="right">The second block.</param>
    /// <returns>True when different.</returns>
    public static bool operator !=(LandblockId left, LandblockId right) => !left.Equals(right);
}
