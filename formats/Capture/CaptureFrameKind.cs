namespace AcPhys.Formats.Capture;

/// <summary>Which frame a capture's positions are in (header <c># frame: block|world</c>).</summary>
internal enum CaptureFrameKind
{
    /// <summary>Each position is in its frame's cell's block frame (x, y ∈ [0, 192) as a client holds it; the default).</summary>
    Block,

    /// <summary>Protocol v1's world frame: metres from the map's south-west corner (docs/protocol.md, "World frame").</summary>
    World,
}
