using System.Text;

namespace AcPhys.Protocol.Child;

/// <summary>
/// One answer line as the child wrote it (its UTF-8 bytes, no line end), spelt as text only when something needs the
/// text: the pipelined reader compares most answers byte by byte with the expected line (issue 26: a string per
/// answer was 1.5 GB of the served pr gate's allocations).
/// </summary>
/// <remarks>The bytes may be the reader's own buffer: valid until the next line is read; <see cref="Text"/> keeps.</remarks>
internal sealed class AnswerLine
{
    private readonly ReadOnlyMemory<byte> bytes;
    private string? text;

    private AnswerLine(ReadOnlyMemory<byte> bytes, string? text)
    {
        this.bytes = bytes;
        this.text = text;
    }

    /// <summary>Gets the line's bytes (see the remarks).</summary>
    public ReadOnlySpan<byte> Bytes => bytes.Span;

    /// <summary>Gets the line's text, decoded as the line reader decodes any line (an invalid sequence reads as U+FFFD).</summary>
    public string Text => text ??= Encoding.UTF8.GetString(bytes.Span);

    /// <summary>Returns a line read as bytes.</summary>
    /// <param name="bytes">The bytes, no line end.</param>
    /// <returns>The line.</returns>
    public static AnswerLine OfBytes(ReadOnlyMemory<byte> bytes) => new(bytes, null);

    /// <summary>Returns a line read as text (the asynchronous reader's): its bytes are the text's UTF-8.</summary>
    /// <param name="text">The text.</param>
    /// <returns>The line.</returns>
    public static AnswerLine OfText(string text) => new(Encoding.UTF8.GetBytes(text), text);
}
