using System.Runtime.CompilerServices;

namespace AcPhys.Formats.Dat;

/// <summary>
/// A field's path in a record (<c>$"{at}.vertices[{i}]"</c>), written only when the reader names its fields: a strict
/// read first runs unnamed and, only when it refuses the record, again named for the message
/// (<see cref="ByteReader.Strictly{T}"/>). Spelling every path of every record cost the served gate more than reading
/// the bytes (issue 26, docs/protocol.md "Speed").
/// </summary>
[InterpolatedStringHandler]
public ref struct FieldPath
{
    private readonly bool write;
    private DefaultInterpolatedStringHandler text;

    /// <summary>Initializes a new instance of the <see cref="FieldPath"/> struct.</summary>
    /// <param name="literalLength">The literal characters (from the compiler).</param>
    /// <param name="formattedCount">The holes (from the compiler).</param>
    /// <param name="reader">The reader: the path is written only when it names fields.</param>
    /// <param name="write">Whether the parts are written.</param>
    public FieldPath(int literalLength, int formattedCount, ByteReader reader, out bool write)
    {
        this.write = write = reader.Named;
        text = write ? new DefaultInterpolatedStringHandler(literalLength, formattedCount) : default;
    }

    /// <summary>Writes a literal part.</summary>
    /// <param name="s">The part.</param>
    public void AppendLiteral(string s) => text.AppendLiteral(s);

    /// <summary>Writes a hole.</summary>
    /// <typeparam name="T">Its type.</typeparam>
    /// <param name="value">Its value.</param>
    public void AppendFormatted<T>(T value) => text.AppendFormatted(value);

    /// <summary>Returns the path, or null when the reader does not name fields.</summary>
    /// <returns>The text.</returns>
    public string? Text() => write ? text.ToStringAndClear() : null;
}
