using System.Text;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Child;

/// <summary>
/// A request line on its way to a pipelining child: kept as the UTF-8 bytes it is written as, and spelt as text only
/// when something quotes it (a message, a difference, a replay). Issue 26: a scene load built as text was decoded
/// from its writer's bytes and encoded back for the pipe — 13 KB each way, 79,000 times a gate.
/// </summary>
/// <remarks>Every quote of a request is cut (<see cref="Wire.Brief"/>, at most 200 characters), so once its bytes are
/// queued a long line keeps only its first <see cref="KeptBytes"/> (more than 200 characters of any UTF-8 text):
/// the thousands of requests in flight then hold a kilobyte each, not a scene's records.</remarks>
internal sealed class RequestLine
{
    /// <summary>The bytes a written line keeps for quoting.</summary>
    public const int KeptBytes = 1024;

    private byte[]? utf8;
    private string? text;
    private bool cut;

    /// <summary>Initializes a new instance of the <see cref="RequestLine"/> class from its UTF-8 bytes.</summary>
    /// <param name="utf8">The line's bytes, no line end (not copied: the caller gives them up).</param>
    public RequestLine(byte[] utf8) => this.utf8 = utf8;

    /// <summary>Initializes a new instance of the <see cref="RequestLine"/> class from its text.</summary>
    /// <param name="text">The line, no line end.</param>
    public RequestLine(string text) => this.text = text;

    /// <summary>Gets the line's UTF-8 bytes, or null when it was given as text.</summary>
    public ReadOnlySpan<byte> Utf8 => utf8;

    /// <summary>Gets a value indicating whether the line was given as bytes.</summary>
    public bool HasUtf8 => utf8 is not null;

    /// <summary>Gets the line's text (decoded once, when first asked); after <see cref="Written"/>, of a long line only its first <see cref="KeptBytes"/> bytes.</summary>
    public string Text => text ??= cut ? Encoding.UTF8.GetString(utf8!) + "…" : Encoding.UTF8.GetString(utf8!);

    /// <summary>Gets a value indicating whether only the first <see cref="KeptBytes"/> were kept (<see cref="Text"/> is not the whole line).</summary>
    public bool IsCut => cut;

    /// <summary>Called once the bytes are queued for the child: a long line keeps only what a quote of it can show.</summary>
    public void Written()
    {
        if (utf8 is { Length: > KeptBytes } all && text is null)
        {
            utf8 = all[..KeptBytes];
            cut = true;
        }
    }

    /// <inheritdoc/>
    public override string ToString() => Text;
}
