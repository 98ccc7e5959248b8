using System.Diagnostics;
using System.Text;

namespace AcPhys.Protocol.Child;

/// <summary>
/// Reads UTF-8 lines from a protocol peer (requests in <c>serve</c>, answers of an implementation) holding at most
/// <see cref="MaxBytes"/> bytes of one line: a longer line is refused with <see cref="LineTooLongException"/> as soon as
/// it passes the limit, and its rest is skipped unread into memory (issue 19: a 100 MB answer line once took 820 MB).
/// </summary>
/// <remarks><para>
/// A line ends at <c>\n</c>; a <c>\r</c> before it is dropped, as <see cref="TextReader.ReadLine"/> does for
/// <c>\r\n</c>. Invalid UTF-8 becomes U+FFFD. A UTF-8 byte order mark at the very start is skipped.
/// </para></remarks>
internal sealed class BoundedLineReader
{
    /// <summary>The default limit: 1 MiB per line.</summary>
    public const int DefaultMaxBytes = 1 << 20;

    private readonly Stream stream;
    private readonly byte[] buffer = new byte[64 * 1024];
    private readonly MemoryStream line = new();
    private int start;
    private int end;
    private bool skipping;
    private bool started;
    private bool resuming;

    /// <summary>Initializes a new instance.</summary>
    /// <param name="stream">The peer's output (read, never closed here).</param>
    /// <param name="maxBytes">The most bytes of one line, newline excluded.</param>
    public BoundedLineReader(Stream stream, int maxBytes = DefaultMaxBytes)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(maxBytes, 1);
        this.stream = stream;
        MaxBytes = maxBytes;
    }

    /// <summary>Gets the most bytes of one line.</summary>
    public int MaxBytes { get; }

    /// <summary>Gets a value indicating whether a whole line is already buffered, so the next read returns without waiting for input.</summary>
    public bool HasBufferedLine => !skipping && end > start && Array.IndexOf(buffer, (byte)'\n', start, end - start) >= 0;

    /// <summary>Reads the next line.</summary>
    /// <returns>The line without its end, or null at end of input.</returns>
    /// <exception cref="LineTooLongException">The line is longer than <see cref="MaxBytes"/>; the next call reads the line after it.</exception>
    /// <remarks>Synchronous all the way down: the stream's own blocking read, no pool thread and no spin-wait per fill
    /// (a standard-input stream's ReadAsync runs its Read on a pool thread; waiting on that cost <c>serve</c> a
    /// sched_yield storm per request, issue 26).</remarks>
    public string? ReadLine() => ReadSynchronously(null);

    /// <summary>Reads the next line synchronously, calling <paramref name="waitForInput"/> before each read of the stream that could block.</summary>
    /// <param name="waitForInput">Waits until the stream has input (or its end, or an error) so the read returns at once;
    /// false when it gave up (the peer is too slow).</param>
    /// <returns>The line without its end, or null at end of input.</returns>
    /// <exception cref="LineTooLongException">The line is longer than <see cref="MaxBytes"/>; the next call reads the line after it.</exception>
    /// <exception cref="TimeoutException"><paramref name="waitForInput"/> gave up; what was read of the line so far is kept.</exception>
    /// <remarks>How the tool reads a child's answers (issue 26): the calling thread waits and reads, where
    /// <see cref="ReadLineAsync"/> cost a pool thread's hand-off and a spin-wait per answer.</remarks>
    public string? ReadLine(Func<bool> waitForInput)
    {
        ArgumentNullException.ThrowIfNull(waitForInput);
        return ReadSynchronously(waitForInput);
    }

    /// <summary>Reads the next line without holding a thread while the peer is silent (the ProcessAdapter waits on it with a timeout).</summary>
    /// <returns>The line without its end, or null at end of input.</returns>
    /// <exception cref="LineTooLongException">The line is longer than <see cref="MaxBytes"/>; the next call reads the line after it.</exception>
    public ValueTask<string?> ReadLineAsync() => Read(synchronous: false, null);

    /// <summary>Reads the next line synchronously as its UTF-8 bytes, as they came (invalid UTF-8 included, the line end and a <c>\r</c> before it dropped).</summary>
    /// <returns>The line's bytes, valid until the next read; null at end of input.</returns>
    /// <exception cref="LineTooLongException">The line is longer than <see cref="MaxBytes"/>; the next call reads the line after it.</exception>
    /// <remarks>How <c>serve</c> reads its requests (issue 26): a valid UTF-8 line is parsed from these bytes, with no
    /// string in between.</remarks>
    public ReadOnlyMemory<byte>? ReadLineUtf8() => ReadUtf8(null);

    /// <summary>Reads the next line as <see cref="ReadLineUtf8()"/> does, waiting for input with <paramref name="waitForInput"/> as <see cref="ReadLine(Func{bool})"/> does.</summary>
    /// <param name="waitForInput">Waits until the stream has input, its end or an error; false gives up (a <see cref="TimeoutException"/>, and the next call goes on with the line held).</param>
    /// <returns>The line's bytes, valid until the next read; null at end of input.</returns>
    /// <exception cref="LineTooLongException">The line is longer than <see cref="MaxBytes"/>.</exception>
    /// <exception cref="TimeoutException"><paramref name="waitForInput"/> gave up.</exception>
    public ReadOnlyMemory<byte>? ReadLineUtf8(Func<bool> waitForInput)
    {
        ArgumentNullException.ThrowIfNull(waitForInput);
        return ReadUtf8(waitForInput);
    }

    private ReadOnlyMemory<byte>? ReadUtf8(Func<bool>? waitForInput)
    {
        if (!Completed(ReadRaw(synchronous: true, waitForInput)))
        {
            return null;
        }

        var bytes = line.GetBuffer().AsMemory(0, (int)line.Length);
        return bytes.Length > 0 && bytes.Span[^1] == (byte)'\r' ? bytes[..^1] : bytes;
    }

    private static T Completed<T>(ValueTask<T> pending)
    {
        Debug.Assert(pending.IsCompleted, "a synchronous read completes before it returns");
        return pending.GetAwaiter().GetResult();
    }

    private string? ReadSynchronously(Func<bool>? waitForInput) => Completed(Read(synchronous: true, waitForInput));

    private async ValueTask<string?> Read(bool synchronous, Func<bool>? waitForInput) =>
        await ReadRaw(synchronous, waitForInput).ConfigureAwait(false) ? Text() : null;

    // Reads the next line into `line`; false at end of input with nothing read.
    private async ValueTask<bool> ReadRaw(bool synchronous, Func<bool>? waitForInput)
    {
        if (skipping && !await SkipRestAsync(synchronous, waitForInput).ConfigureAwait(false))
        {
            return false;
        }

        if (!resuming)
        {
            line.SetLength(0);
        }

        resuming = false;
        while (true)
        {
            if (start == end && !await FillAsync(synchronous, waitForInput).ConfigureAwait(false))
            {
                return line.Length != 0;
            }

            int newline = Array.IndexOf(buffer, (byte)'\n', start, end - start);
            int take = (newline < 0 ? end : newline) - start;
            // A "\r" just before the "\n" does not count; without the "\n" yet, one byte more may be that "\r".
            long length = line.Length + take - (newline < 0 ? 1 : EndsWithReturn(newline, take));
            if (length > MaxBytes)
            {
                // Drop what is held and what is buffered of this line; the rest is skipped on the next call.
                line.SetLength(0);
                skipping = newline < 0;
                start = newline < 0 ? end : newline + 1;
                throw new LineTooLongException(MaxBytes);
            }

            line.Write(buffer, start, take);
            if (newline >= 0)
            {
                start = newline + 1;
                return true;
            }

            start = end;
        }
    }

    private int EndsWithReturn(int newline, int take) =>
        (take > 0 ? buffer[newline - 1] : line.Length > 0 ? line.GetBuffer()[line.Length - 1] : (byte)0) == (byte)'\r' ? 1 : 0;

    private string Text()
    {
        var bytes = line.GetBuffer().AsSpan(0, (int)line.Length);
        if (bytes.Length > 0 && bytes[^1] == (byte)'\r')
        {
            bytes = bytes[..^1];
        }

        return Encoding.UTF8.GetString(bytes);
    }

    private async ValueTask<bool> FillAsync(bool synchronous, Func<bool>? waitForInput)
    {
        if (waitForInput is not null && !waitForInput())
        {
            resuming = !skipping; // the next call goes on with the line held so far
            throw new TimeoutException("no input within the wait");
        }

        start = 0;
        end = synchronous
            ? stream.Read(buffer, 0, buffer.Length)
            : await stream.ReadAsync(buffer.AsMemory(0, buffer.Length)).ConfigureAwait(false);
        if (!started && end > 0)
        {
            started = true;
            if (end >= 3 && buffer[0] == 0xEF && buffer[1] == 0xBB && buffer[2] == 0xBF)
            {
                start = 3;
            }
        }

        return end > start || (end > 0 && await FillAsync(synchronous, waitForInput).ConfigureAwait(false));
    }

    // Skips to just after the next newline; false at end of input.
    private async ValueTask<bool> SkipRestAsync(bool synchronous, Func<bool>? waitForInput)
    {
        while (true)
        {
            if (start == end && !await FillAsync(synchronous, waitForInput).ConfigureAwait(false))
            {
                skipping = false;
                return false;
            }

            int newline = Array.IndexOf(buffer, (byte)'\n', start, end - start);
            if (newline >= 0)
            {
                start = newline + 1;
                skipping = false;
                return true;
            }

            start = end;
        }
    }
}
