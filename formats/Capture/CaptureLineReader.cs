namespace AcPhys.Formats.Capture;

/// <summary>What both capture readers share: the line source and the counts every reader reports.</summary>
/// <param name="stream">The input (owned: disposed with the reader).</param>
/// <param name="source">The file name for messages.</param>
internal abstract class CaptureLineReader(Stream stream, string source) : ICaptureReader
{
    /// <inheritdoc/>
    public string Source => LineSource.Source;

    /// <inheritdoc/>
    public abstract CaptureHeader Header { get; }

    /// <inheritdoc/>
    public long Lines => LineSource.Number;

    /// <inheritdoc/>
    public long Ignored { get; protected set; }

    /// <inheritdoc/>
    public long Position => LineSource.Position;

    /// <inheritdoc/>
    public long Length => LineSource.Length;

    /// <summary>Gets the lines of the input.</summary>
    protected CaptureLines LineSource { get; } = new(stream, source);

    /// <inheritdoc/>
    public abstract bool Read(out CaptureFrame frame);

    /// <inheritdoc/>
    public void Dispose() => LineSource.Dispose();
}
