using System.Buffers.Binary;
using System.Numerics;
using System.Runtime.CompilerServices;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>
/// Bounded little-endian record reader. Every failure is a <see cref="InputFormatException"/> naming the record, the
/// field and its byte offset; counts are checked against the remaining bytes before anything is allocated.
/// </summary>
/// <param name="data">The record bytes.</param>
/// <param name="kind">The record type for messages (<c>EnvCell</c>).</param>
/// <param name="id">The record id for messages.</param>
/// <param name="named">Whether field paths are spelled out (<see cref="Named"/>).</param>
/// <remarks><para>
/// A reader that does not name fields checks exactly what a naming one checks; only its messages lack the field. Read
/// through <see cref="Strictly{T}"/>, which repeats a refused read named, so every message a caller sees is whole.
/// </para></remarks>
public sealed class ByteReader(byte[] data, string kind, uint id, bool named = true)
{
    /// <summary>Gets a value indicating whether field paths are spelled out: <see cref="Path"/> returns null and the
    /// fields' names are partial when not (the unnamed first pass of <see cref="Strictly{T}"/>).</summary>
    public bool Named => named;

    /// <summary>Gets the offset of the next byte.</summary>
    public int Position { get; private set; }

    /// <summary>Gets the number of unread bytes.</summary>
    public int Remaining => data.Length - Position;

    /// <summary>Gets the name used in messages (<c>EnvCell 0x01020100</c>).</summary>
    public string Record => kind + " " + RecordIds.Text(id);

    /// <summary>Reads a record unnamed and, only when that refuses it, again named, so the refusal carries the field's
    /// whole path. Both passes check the same things; a record the unnamed pass accepts is never read twice.</summary>
    /// <typeparam name="T">What the read returns.</typeparam>
    /// <param name="read">The read, given whether to name fields.</param>
    /// <returns>The value.</returns>
    /// <exception cref="InputFormatException">The record is refused (the named pass's message).</exception>
    public static T Strictly<T>(Func<bool, T> read)
    {
        try
        {
            return read(false);
        }
        catch (InputFormatException)
        {
            read(true);
            throw new InvalidOperationException("a dat record refused unnamed was accepted named: a reader names a field by a check it makes");
        }
    }

    /// <summary>Spells out a field path when fields are named (<see cref="FieldPath"/>).</summary>
    /// <param name="path">The path.</param>
    /// <returns>The path, or null when not <see cref="Named"/>.</returns>
    public string? Path([InterpolatedStringHandlerArgument("")] ref FieldPath path) => path.Text();

    /// <summary>Throws the format error for a field at an offset.</summary>
    /// <param name="field">The field.</param>
    /// <param name="offset">Its byte offset.</param>
    /// <param name="message">The problem.</param>
    /// <returns>Never returns.</returns>
    public InputFormatException Error(string? field, int offset, string message) =>
        new($"{Record}: {field} at byte {offset}: {message}");

    /// <summary>Refuses the record unless a condition holds.</summary>
    /// <param name="ok">The condition.</param>
    /// <param name="field">The field.</param>
    /// <param name="offset">Its byte offset.</param>
    /// <param name="message">The problem.</param>
    public void Require(bool ok, string? field, int offset, string message)
    {
        if (!ok)
        {
            throw Error(field, offset, message);
        }
    }

    /// <summary>Refuses the record unless a condition holds; the message is formatted only when it does not (<see cref="FailureText"/>).</summary>
    /// <param name="ok">The condition.</param>
    /// <param name="field">The field.</param>
    /// <param name="offset">Its byte offset.</param>
    /// <param name="message">The problem.</param>
    public void Require(bool ok, string? field, int offset, [InterpolatedStringHandlerArgument("ok")] ref FailureText message)
    {
        if (!ok)
        {
            throw Error(field, offset, message.Text());
        }
    }

    /// <summary>Reads a byte.</summary>
    /// <param name="field">The field.</param>
    /// <returns>The value.</returns>
    public byte U8(string? field) => Take(1, field)[0];

    /// <summary>Reads a u16.</summary>
    /// <param name="field">The field.</param>
    /// <returns>The value.</returns>
    public ushort U16(string? field) => BinaryPrimitives.ReadUInt16LittleEndian(Take(2, field));

    /// <summary>Reads an i16.</summary>
    /// <param name="field">The field.</param>
    /// <returns>The value.</returns>
    public short I16(string? field) => BinaryPrimitives.ReadInt16LittleEndian(Take(2, field));

    /// <summary>Reads a u32.</summary>
    /// <param name="field">The field.</param>
    /// <returns>The value.</returns>
    public uint U32(string? field) => BinaryPrimitives.ReadUInt32LittleEndian(Take(4, field));

    /// <summary>Reads an i32.</summary>
    /// <param name="field">The field.</param>
    /// <returns>The value.</returns>
    public int I32(string? field) => BinaryPrimitives.ReadInt32LittleEndian(Take(4, field));

    /// <summary>Reads an f32 (any bits; callers that need finite values check).</summary>
    /// <param name="field">The field.</param>
    /// <returns>The value.</returns>
    public float F32(string? field) => BitConverter.UInt32BitsToSingle(U32(field));

    /// <summary>Reads a Vector3 whose components must be finite.</summary>
    /// <param name="field">The field.</param>
    /// <returns>The value.</returns>
    public Vector3 Vec(string? field)
    {
        int at = Position;
        // All three there: one read (a short record is refused component by component, each where it ends).
        var v = data.Length - at >= 12 ? Floats3(Take(12, field)) : new Vector3(F32(field), F32(field), F32(field));
        Require(float.IsFinite(v.X) && float.IsFinite(v.Y) && float.IsFinite(v.Z), field, at, "non-finite value");
        return v;
    }

    /// <summary>Reads a Frame (origin, then W, X, Y, Z; facts §5.8), all finite.</summary>
    /// <param name="field">The field.</param>
    /// <returns>Origin and rotation.</returns>
    public (Vector3 Origin, Quaternion Rotation) Frame(string? field)
    {
        var origin = Vec(Sub(field, ".origin"));
        int at = Position;
        float w = F32(Sub(field, ".rotation")), x = F32(Sub(field, ".rotation")), y = F32(Sub(field, ".rotation")), z = F32(Sub(field, ".rotation"));
        Require(float.IsFinite(w) && float.IsFinite(x) && float.IsFinite(y) && float.IsFinite(z), Sub(field, ".rotation"), at, "non-finite quaternion");
        return (origin, new Quaternion(x, y, z, w));
    }

    /// <summary>Reads a Plane, finite.</summary>
    /// <param name="field">The field.</param>
    /// <returns>The plane.</returns>
    public CellPlane Plane(string? field)
    {
        var n = Vec(Sub(field, ".normal"));
        int at = Position;
        float d = F32(Sub(field, ".d"));
        Require(float.IsFinite(d), Sub(field, ".d"), at, "non-finite value");
        return new CellPlane(n, d);
    }

    /// <summary>Reads a Sphere, finite.</summary>
    /// <param name="field">The field.</param>
    /// <returns>The sphere.</returns>
    public Sphere Sphere(string? field)
    {
        var c = Vec(Sub(field, ".center"));
        int at = Position;
        float r = F32(Sub(field, ".radius"));
        string? bad = AcPhys.Formats.Values.SphereRadius.Problem(r);
        Require(bad is null, Sub(field, ".radius"), at, bad ?? string.Empty);
        return new Sphere(c, r);
    }

    /// <summary>Checks a count against the remaining bytes (each item at least <paramref name="minBytes"/>).</summary>
    /// <param name="count">The count read.</param>
    /// <param name="minBytes">The smallest size of one item.</param>
    /// <param name="field">The count's field.</param>
    /// <param name="at">The count's offset.</param>
    /// <returns>The count as an int.</returns>
    public int Count(long count, int minBytes, string? field, int at)
    {
        Require(count >= 0 && count * minBytes <= Remaining, field, at, $"count {count} needs at least {count * minBytes} bytes, {Remaining} remain");
        return (int)count;
    }

    /// <summary>Skips the ALIGN padding: (4 − pos % 4) % 4 bytes from the record start.</summary>
    /// <param name="field">What the padding follows.</param>
    public void Align(string? field) => Take((4 - (Position % 4)) % 4, Sub(field, " (ALIGN padding)"));

    /// <summary>Whether the next <paramref name="n"/> bytes are all there and all zero (the position does not move).</summary>
    /// <param name="n">How many.</param>
    /// <returns>True when they are.</returns>
    public bool NextAreZero(int n) => n <= Remaining && !data.AsSpan(Position, n).ContainsAnyExcept((byte)0);

    /// <summary>Moves past <paramref name="n"/> bytes a caller has already checked (<see cref="NextAreZero"/>).</summary>
    /// <param name="n">How many.</param>
    public void Skip(int n)
    {
        ArgumentOutOfRangeException.ThrowIfGreaterThan(n, Remaining);
        Position += n;
    }

    /// <summary>Refuses trailing bytes.</summary>
    public void End() => Require(Remaining == 0, "end of record", Position, $"{Remaining} trailing byte(s)");

    // A member's path below a field, spelled only when fields are named.
    private string? Sub(string? field, string member) => named ? field + member : null;

    private static Vector3 Floats3(ReadOnlySpan<byte> bytes) => new(
        BinaryPrimitives.ReadSingleLittleEndian(bytes),
        BinaryPrimitives.ReadSingleLittleEndian(bytes[4..]),
        BinaryPrimitives.ReadSingleLittleEndian(bytes[8..]));

    // The hot path of every field (issue 26): one comparison; the refusal is built out of line.
    private ReadOnlySpan<byte> Take(int n, string? field)
    {
        int at = Position;
        if (n > data.Length - at)
        {
            throw Ends(n, field);
        }

        Position = at + n;
        return new ReadOnlySpan<byte>(data, at, n);
    }

    [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
    private InputFormatException Ends(int n, string? field) => Error(field, Position, $"record ends ({Remaining} byte(s) left, {n} needed)");
}
