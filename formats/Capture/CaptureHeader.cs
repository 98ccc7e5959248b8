using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Capture;

/// <summary>What a capture declares about itself (header comments before the first frame, or the importer's options).</summary>
/// <param name="Frame">The positions' frame.</param>
/// <param name="Body">The body's spheres (offsets from the position, radii; sphere 0 decides the pick), or empty when the capture names none.</param>
internal sealed record CaptureHeader(CaptureFrameKind Frame, IReadOnlyList<BodySphere> Body)
{
    /// <summary>Gets the default header: block frame, no body named.</summary>
    public static CaptureHeader Default { get; } = new(CaptureFrameKind.Block, []);
}
