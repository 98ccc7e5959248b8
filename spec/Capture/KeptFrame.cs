using AcPhys.Core;
using AcPhys.Formats.Capture;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Capture;

/// <summary>A frame copied out of the stream (the checker keeps a few per finding, for the minimiser).</summary>
/// <param name="Number">The frame number.</param>
/// <param name="Line">The file line.</param>
/// <param name="World">The position in world metres, with the decimals the log printed.</param>
/// <param name="Body">The body at the frame (empty: not named).</param>
/// <param name="Before">The port's cell before the frame.</param>
/// <param name="Cell">The port's cell after it (none: not recorded).</param>
/// <param name="Candidates">The port's candidates, or null when not reported.</param>
/// <param name="Verdict">The checker's verdict.</param>
internal sealed record KeptFrame(long Number, long Line, PrintedPoint World, BodySphere[] Body, CellId Before, CellId Cell, CellId[]? Candidates, VerdictKind Verdict)
{
    /// <summary>Gets the world x.</summary>
    public double WorldX => World.X;

    /// <summary>Gets the world y.</summary>
    public double WorldY => World.Y;

    /// <summary>Copies a frame out of the stream.</summary>
    /// <param name="q">The frame as judged.</param>
    /// <param name="verdict">Its verdict.</param>
    /// <returns>The copy.</returns>
    public static KeptFrame Of(in CaptureQuery q, VerdictKind verdict) =>
        new(q.Frame.Number, q.Frame.Line, q.Frame.Position with { X = q.WorldX, Y = q.WorldY }, [.. q.Body], q.Before, q.Frame.Cell, q.Frame.HasCandidates ? q.Frame.Candidates.ToArray() : null, verdict);

    /// <summary>Returns the frame as a judge's query (world frame), with the cell the port held before it.</summary>
    /// <param name="before">The port's cell before the frame.</param>
    /// <returns>The query.</returns>
    public CaptureQuery Query(CellId before) =>
        new(new CaptureFrame(Number, Line, Cell, World, float.NaN) { HasCandidates = Candidates is not null, Candidates = Candidates ?? [] }, before, CaptureFrameKind.World, Body);
}
