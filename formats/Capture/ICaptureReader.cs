namespace AcPhys.Formats.Capture;

/// <summary>
/// A capture read as a stream: one frame at a time, in constant memory (no list of frames is ever held). Every defect is
/// an <see cref="InputFormatException"/> naming the file, the line and what was expected.
/// </summary>
internal interface ICaptureReader : IDisposable
{
    /// <summary>Gets the file name used in messages.</summary>
    string Source { get; }

    /// <summary>Gets the header: read before the first frame (native headers must precede every frame).</summary>
    CaptureHeader Header { get; }

    /// <summary>Gets the lines read so far.</summary>
    long Lines { get; }

    /// <summary>Gets the lines read so far that were no frame (comments, blank lines, an acdream log's other lines).</summary>
    long Ignored { get; }

    /// <summary>Gets the bytes consumed so far (for progress).</summary>
    long Position { get; }

    /// <summary>Gets the length of the input in bytes, or −1 when unknown.</summary>
    long Length { get; }

    /// <summary>Reads the next frame.</summary>
    /// <param name="frame">The frame (its candidates valid until the next call).</param>
    /// <returns>False at the end of the capture.</returns>
    /// <exception cref="InputFormatException">A malformed or hostile line.</exception>
    bool Read(out CaptureFrame frame);
}
