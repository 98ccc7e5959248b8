using System.Text.Unicode;

namespace AcPhys.Formats.Capture;

/// <summary>
/// The lines of a capture, read through one buffer (no string per line): each line a span of bytes without its line
/// end (<c>\n</c> or <c>\r\n</c>). Hostile input is refused with the file and line: a line longer than
/// <see cref="MaxLineBytes"/>, a NUL byte (binary data), bytes that are not UTF-8, a last line with no line end (a capture
/// cut off while written, when the caller says such a line matters).
/// </summary>
internal sealed class CaptureLines : IDisposable
{
    /// <summary>The longest line, in bytes, line end excluded (a frame line is under 200 bytes; a candidate list of 1,024 ids under 12 KiB).</summary>
    public const int MaxLineBytes = 65536;

    private readonly Stream stream;
    private readonly byte[] buffer = new byte[MaxLineBytes * 2];
    private int start;
    private int end;
    private bool eof;
    private long consumed;

    /// <summary>Initializes a new instance of the <see cref="CaptureLines"/> class.</summary>
    /// <param name="stream">The input (owned: disposed with this).</param>
    /// <param name="source">The file name for messages.</param>
    public CaptureLines(Stream stream, string source)
    {
        this.stream = stream;
        Source = source;
        Length = stream.CanSeek ? stream.Length : -1;
    }

    /// <summary>Gets the file name for messages.</summary>
    public string Source { get; }

    /// <summary>Gets the number of the line last returned (1-based; 0 before the first).</summary>
    public long Number { get; private set; }

    /// <summary>Gets the bytes consumed so far.</summary>
    public long Position => consumed;

    /// <summary>Gets the input's length in bytes, or −1.</summary>
    public long Length { get; }

    /// <summary>Gets a value indicating whether the line last returned had no line end (the file's last bytes).</summary>
    public bool Unterminated { get; private set; }

    /// <summary>Reads the next line.</summary>
    /// <param name="line">The line's bytes, valid until the next call.</param>
    /// <returns>False at the end of the input.</returns>
    /// <exception cref="InputFormatException">A line too long, a NUL byte or invalid UTF-8.</exception>
    public bool Next(out ReadOnlySpan<byte> line)
    {
        while (true)
        {
            var pending = buffer.AsSpan(start, end - start);
            int nl = pending.IndexOf((byte)'\n');
            if (nl >= 0)
            {
                Unterminated = false;
                return Take(nl, nl + 1, out line);
            }

            if (pending.Length > MaxLineBytes)
            {
                throw Error(Number + 1, $"line longer than {MaxLineBytes:N0} bytes (expected one frame a line)");
            }

            if (eof)
            {
                if (pending.IsEmpty)
                {
                    line = default;
                    return false;
                }

                Unterminated = true;
                return Take(pending.Length, pending.Length, out line);
            }

            Fill();
        }
    }

    /// <summary>Returns the format error for a line.</summary>
    /// <param name="lineNumber">The line.</param>
    /// <param name="what">What is wrong and what was expected.</param>
    /// <returns>The exception.</returns>
    public InputFormatException Error(long lineNumber, string what) => new($"{Source}:{lineNumber}: {what}");

    /// <inheritdoc/>
    public void Dispose() => stream.Dispose();

    private bool Take(int length, int advance, out ReadOnlySpan<byte> line)
    {
        Number++;
        line = buffer.AsSpan(start, length);
        start += advance;
        consumed += advance;
        if (line.Length > MaxLineBytes)
        {
            throw Error(Number, $"line longer than {MaxLineBytes:N0} bytes (expected one frame a line)");
        }

        if (line.Length > 0 && line[^1] == (byte)'\r')
        {
            line = line[..^1];
        }

        if (line.IndexOf((byte)0) >= 0)
        {
            throw Error(Number, "a NUL byte: binary data, not a text capture");
        }

        if (line.ContainsAnyInRange((byte)0x80, (byte)0xFF) && !Utf8.IsValid(line))
        {
            throw Error(Number, "not valid UTF-8 text");
        }

        return true;
    }

    private void Fill()
    {
        if (start > 0)
        {
            Buffer.BlockCopy(buffer, start, buffer, 0, end - start);
            end -= start;
            start = 0;
        }

        int n = stream.Read(buffer, end, buffer.Length - end);
        if (n == 0)
        {
            eof = true;
        }

        end += n;
    }
}
