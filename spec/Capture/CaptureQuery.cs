using AcPhys.Core;
using AcPhys.Formats.Capture;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Capture;

/// <summary>
/// One frame as a judge sees it: the frame (the port's answer: its cell after the frame and, when reported, its
/// candidates), the cell the port held before it (the threading: docs/ports.md, "Your own sessions"), the frame the
/// positions are in, and the body at this frame (sphere 0's radius from the line when it gives one).
/// </summary>
/// <param name="Frame">The frame, with the port's answer.</param>
/// <param name="Before">The port's cell before the frame (the previous frame's cell, or what the line says), or <see cref="CellId.None"/> at the start.</param>
/// <param name="Kind">Which frame <see cref="CaptureFrame.Position"/> is in.</param>
/// <param name="Body">The body's spheres at this frame (offsets and radii; sphere 0 decides the pick). Reused by the checker: copy it to keep it.</param>
internal readonly record struct CaptureQuery(CaptureFrame Frame, CellId Before, CaptureFrameKind Kind, BodySphere[] Body)
{
    /// <summary>Gets the position's world x (metres from the map's south-west corner), exact in double.</summary>
    public double WorldX => Kind == CaptureFrameKind.World ? Frame.Position.X : (LandDefs.BlockLength * (double)Frame.Cell.BlockX) + Frame.Position.X;

    /// <summary>Gets the position's world y.</summary>
    public double WorldY => Kind == CaptureFrameKind.World ? Frame.Position.Y : (LandDefs.BlockLength * (double)Frame.Cell.BlockY) + Frame.Position.Y;

    /// <summary>Gets a value indicating whether the frame involves an env cell (the port's cell before or after it): an indoor frame.</summary>
    public bool IsIndoor => Frame.Cell.IsIndoorByLowWord || Before.IsIndoorByLowWord;
}
