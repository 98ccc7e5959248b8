using AcPhys.Core;

namespace AcPhys.Formats.Capture;

/// <summary>
/// One frame of a capture: what the port reported after the frame. A reader reuses its buffers, so a frame (its
/// <see cref="Candidates"/>) is valid until the reader's next read; copy what must outlive it.
/// </summary>
/// <param name="Number">The frame number (native: the file's <c>frame</c> column; acdream: the probe line's ordinal, from 1).</param>
/// <param name="Line">The line of the file the frame was read from (1-based).</param>
/// <param name="Cell">The port's current cell after the frame, or <see cref="CellId.None"/> when the log does not say (a last cellset line).</param>
/// <param name="Position">The body's position as printed: in <see cref="Cell"/>'s block frame (<see cref="CaptureFrameKind.Block"/>) or in metres from the map's south-west corner (<see cref="CaptureFrameKind.World"/>).</param>
/// <param name="Radius">Sphere 0's radius given on the line, or NaN when the line gives none (the header's body).</param>
internal readonly record struct CaptureFrame(long Number, long Line, CellId Cell, PrintedPoint Position, float Radius)
{
    /// <summary>Gets the port's cell before the frame when the log says it (an acdream transit's old cell, a cellset's seed), or <see cref="CellId.None"/>: the previous frame's cell.</summary>
    public CellId Before { get; init; }

    /// <summary>Gets a value indicating whether the line reported the candidate list (<see cref="Candidates"/>).</summary>
    public bool HasCandidates { get; init; }

    /// <summary>Gets the candidate cells as reported, in the port's order (valid until the reader's next read).</summary>
    public ReadOnlyMemory<CellId> Candidates { get; init; }
}
