using AcPhys.Core;

namespace AcPhys.Formats.Capture;

/// <summary>What an importer needs beside the file: the acdream family's world origin and the body's radius.</summary>
/// <param name="WorldOrigin">The landblock whose south-west corner is the client's world (0, 0) (<c>--world-origin 0xAABB</c>), for <see cref="CaptureFormat.Acdream"/>.</param>
/// <param name="Radius">The body's radius (<c>--radius</c>), or null.</param>
internal sealed record CaptureOptions(LandblockId? WorldOrigin, float? Radius);

/// <summary>Opens a capture file in a format (read only: the file is never written).</summary>
internal static class CaptureReaders
{
    /// <summary>Opens a stream as a capture.</summary>
    /// <param name="stream">The input (owned by the reader).</param>
    /// <param name="source">The name for messages.</param>
    /// <param name="format">The format.</param>
    /// <param name="options">The importer's options.</param>
    /// <returns>The reader.</returns>
    /// <exception cref="InputFormatException">A malformed header.</exception>
    /// <exception cref="ArgumentException">An acdream log without a world origin.</exception>
    public static ICaptureReader Open(Stream stream, string source, CaptureFormat format, CaptureOptions options) =>
        format == CaptureFormat.Acdream
            ? new AcdreamCaptureReader(stream, source, options.WorldOrigin ?? throw new ArgumentException("an acdream log needs its world origin (--world-origin 0xAABB)", nameof(options)), options.Radius)
            : new NativeCaptureReader(stream, source);

    /// <summary>Opens a file as a capture, read through a 64 KiB buffer.</summary>
    /// <param name="path">The file.</param>
    /// <param name="format">The format.</param>
    /// <param name="options">The importer's options.</param>
    /// <returns>The reader.</returns>
    public static ICaptureReader Open(string path, CaptureFormat format, CaptureOptions options) =>
        Open(new FileStream(path, FileMode.Open, FileAccess.Read, FileShare.Read, 1 << 16, FileOptions.SequentialScan), path, format, options);
}
