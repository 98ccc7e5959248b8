namespace AcPhys.Formats.Capture;

/// <summary>Which kind of log a capture file is (<c>acphys capture check --format</c>, docs/corpus-format.md, "Captures").</summary>
internal enum CaptureFormat
{
    /// <summary>The native capture format: one tab-separated frame a line, <c>frame cell x y z [radius] [candidates]</c>.</summary>
    Native,

    /// <summary>The acdream family's probe lines (<c>[cell-transit]</c>, <c>[cellset-build]</c>), in the client's world frame; other lines ignored.</summary>
    Acdream,
}

/// <summary>The names of <see cref="CaptureFormat"/> on the command line.</summary>
internal static class CaptureFormats
{
    /// <summary>Gets the names, in the order of <see cref="CaptureFormat"/>.</summary>
    public static IReadOnlyList<string> Names { get; } = ["native", "acdream"];

    /// <summary>Parses a format name.</summary>
    /// <param name="text">The name (null: native).</param>
    /// <param name="format">The format.</param>
    /// <returns>False for an unknown name.</returns>
    public static bool TryParse(string? text, out CaptureFormat format)
    {
        format = text switch { null or "native" => CaptureFormat.Native, "acdream" => CaptureFormat.Acdream, _ => (CaptureFormat)(-1) };
        return (int)format >= 0;
    }
}
