using System.Runtime.CompilerServices;

namespace AcPhys.Formats.Dat;

/// <summary>
/// The message of a check, written only when the check fails: <c>Require(ok, $"...")</c> formats nothing while
/// <c>ok</c> holds. A strict reader checks every field of every record it reads, so formatting each message up front
/// cost more than the reading itself (issue 26, docs/protocol.md "Speed").
/// </summary>
[InterpolatedStringHandler]
public ref struct FailureText
{
    private DefaultInterpolatedStringHandler text;

    /// <summary>Initializes a new instance of the <see cref="FailureText"/> struct.</summary>
    /// <param name="literalLength">The literal characters (from the compiler).</param>
    /// <param name="formattedCount">The holes (from the compiler).</param>
    /// <param name="ok">The check's condition: when it holds nothing is written.</param>
    /// <param name="write">Whether the parts are written.</param>
    public FailureText(int literalLength, int formattedCount, bool ok, out bool write)
    {
        write = !ok;
        text = write ? new DefaultInterpolatedStringHandler(literalLength, formattedCount) : default;
    }

    /// <summary>Writes a literal part.</summary>
    /// <param name="s">The part.</param>
    public void AppendLiteral(string s) => text.AppendLiteral(s);

    /// <summary>Writes a hole.</summary>
    /// <typeparam name="T">Its type.</typeparam>
    /// <param name="value">Its value.</param>
    public void AppendFormatted<T>(T value) => text.AppendFormatted(value);

    /// <summary>Writes a hole with a format.</summary>
    /// <typeparam name="T">Its type.</typeparam>
    /// <param name="value">Its value.</param>
    /// <param name="format">The format.</param>
    public void AppendFormatted<T>(T value, string? format) => text.AppendFormatted(value, format);

    /// <summary>Returns the message (only called when the check failed).</summary>
    /// <returns>The text.</returns>
    public string Text() => text.ToStringAndClear();
}
