namespace AcPhys.Core;

/// <summary>
/// Represents a 32-bit Asheron's Call cell id <c>0xXXYYCCCC</c>: landblock column byte, landblock row byte
/// and a 16-bit low word (facts §1.1).
/// </summary>
/// <remarks>
/// <para>Any 32-bit pattern can be held: validity is a question asked of the id (<see cref="IsLand"/>,
/// <see cref="LandDefs.CellInRange"/>), never assumed. <c>default</c> is id 0, "no cell", the value every
/// LandDefs function returns on failure.</para>
/// <para>Low word classes: 0x0001..0x0040 land, 0x0100..0xFFFD env, 0xFFFF the landblock itself; anything else
/// is invalid.</para>
/// </remarks>
/// <threadsafety>Immutable value type.</threadsafety>
public readonly struct CellId : IEquatable<CellId>, IComparable<CellId>
{
    /// <summary>The id 0: no cell.</summary>
    public static readonly CellId None;

    /// <summary>Initializes a cell id from its raw 32-bit pattern (every pattern is representable).</summary>
    /// <param name="value">The raw id.</param>
    public CellId(uint value) => Value = value;

    /// <summary>Initializes a cell id from its three parts.</summary>
    /// <param name="blockX">Landblock column byte (bits 31..24).</param>
    /// <param name="blockY">Landblock row byte (bits 23..16).</param>
    /// <param name="low">Low word (bits 15..0).</param>
    public CellId(byte blockX, byte blockY, ushort low) => Value = ((uint)blockX << 24) | ((uint)blockY << 16) | low;

    /// <summary>Gets the raw 32-bit id.</summary>
    public uint Value { get; }

    /// <summary>Gets the landblock column byte <c>bx</c> (bits 31..24).</summary>
    public byte BlockX => (byte)(Value >> 24);

    /// <summary>Gets the landblock row byte <c>by</c> (bits 23..16).</summary>
    public byte BlockY => (byte)(Value >> 16);

    /// <summary>Gets the low word (bits 15..0).</summary>
    public ushort Low => (ushort)Value;

    /// <summary>Gets the landblock this id names (its high word).</summary>
    public LandblockId Landblock => new((ushort)(Value >> 16));

    /// <summary>Gets a value indicating whether this is id 0.</summary>
    public bool IsNone => Value == 0;

    /// <summary>Gets a value indicating whether the low word is a land (outdoor) cell, 0x0001..0x0040.</summary>
    public bool IsLand => Low is >= LandDefs.FirstLandCellId and <= LandDefs.LastLandCellId;

    /// <summary>Gets a value indicating whether the low word is an env (indoor) cell, 0x0100..0xFFFD.</summary>
    public bool IsEnv => Low is >= LandDefs.FirstEnvCellId and <= LandDefs.LastEnvCellId;

    /// <summary>Gets a value indicating whether the low word is 0xFFFF, the landblock itself.</summary>
    public bool IsBlock => Low == LandDefs.BlockCellId;

    /// <summary>
    /// Gets a value indicating whether membership code treats this id as indoor: <c>low ≥ 0x100</c>.
    /// Note this includes the block id 0xFFFF (facts §1.1), so a block-id position must be normalised first.
    /// </summary>
    public bool IsIndoorByLowWord => Low >= LandDefs.FirstEnvCellId;

    /// <summary>Returns the id of the same landblock with another low word.</summary>
    /// <param name="low">The new low word.</param>
    /// <returns>The id <c>(this &amp; 0xFFFF0000) | low</c>.</returns>
    public CellId WithLow(ushort low) => new((Value & LandDefs.BlockMask) | low);

    /// <summary>Formats the id as <c>0xAABBCCCC</c> (eight upper-case hex digits).</summary>
    /// <returns>The formatted id.</returns>
    public override string ToString() => Text.CellIdText.Format(this);

    /// <inheritdoc/>
    public bool Equals(CellId other) => Value == other.Value;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is CellId other && Equals(other);

    /// <inheritdoc/>
    public override int GetHashCode() => (int)Value;

    /// <inheritdoc/>
    public int CompareTo(CellId other) => Value.CompareTo(other.Value);

    /// <summary>Compares two ids for equality.</summary>
    /// <param name="left">The first id.</param>
    /// <param name="right">The second id.</param>
    /// <returns>True when the raw values are equal.</returns>
    public static bool operator ==(CellId left, CellId right) => left.Equals(right);

    /// <summary>Compares two ids for inequality.</summary>
    /// <param name="left">The first id.</param>
    /// <param name="right">The second id.</param>
    /// <returns>True when the raw values differ.</returns>
    public static bool operator !=(CellId left, CellId right) => !left.Equals(right);

    /// <summary>Orders two ids by raw value.</summary>
    /// <param name="left">The first id.</param>
    /// <param name="right">The second id.</param>
    /// <returns>True when left sorts before right.</returns>
    public static bool operator <(CellId left, CellId right) => left.Value < right.Value;

    /// <summary>Orders two ids by raw value.</summary>
    /// <param name="left">The first id.</param>
    /// <param name="right">The second id.</param>
    /// <returns>True when left sorts after right.</returns>
    public static bool operator >(CellId left, CellId right) => left.Value > right.Value;

    /// <summary>Orders two ids by raw value.</summary>
    /// <param name="left">The first id.</param>
    /// <param name="right">The second id.</param>
    /// <returns>True when left sorts before or equal to right.</returns>
    public static bool operator <=(CellId left, CellId right) => left.Value <= right.Value;

    /// <summary>Orders two ids by raw value.</summary>
    /// <param name="left">The first id.</param>
    /// <param name="right">The second id.</param>
    /// <returns>True when left sorts after or equal to right.</returns>
    public static bool operator >=(CellId left, CellId right) => left.Value >= right.Value;
}
