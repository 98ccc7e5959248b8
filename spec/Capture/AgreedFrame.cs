using AcPhys.Core;
using AcPhys.Formats.Capture;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Capture;

/// <summary>
/// The last agreed frame, held in reused buffers (the checker updates it at every agreeing frame without allocating)
/// and copied into a <see cref="KeptFrame"/> only when a span opens after it.
/// </summary>
internal sealed class AgreedFrame
{
    private readonly CellId[] candidates = new CellId[CaptureText.MaxCandidates];
    private BodySphere[] body = [];
    private int count;
    private bool hasCandidates;
    private long number;
    private long line;
    private PrintedPoint world;
    private CellId before;
    private CellId cell;

    /// <summary>Gets a value indicating whether a frame has agreed yet.</summary>
    public bool Any { get; private set; }

    /// <summary>Holds an agreeing frame.</summary>
    /// <param name="q">The frame as judged.</param>
    public void Set(in CaptureQuery q)
    {
        Any = true;
        number = q.Frame.Number;
        line = q.Frame.Line;
        world = q.Frame.Position with { X = q.WorldX, Y = q.WorldY };
        before = q.Before;
        cell = q.Frame.Cell;
        hasCandidates = q.Frame.HasCandidates;
        count = hasCandidates ? q.Frame.Candidates.Length : 0;
        q.Frame.Candidates.Span[..count].CopyTo(candidates);
        if (body.Length != q.Body.Length)
        {
            body = new BodySphere[q.Body.Length];
        }

        q.Body.CopyTo(body, 0);
    }

    /// <summary>Returns the frame as a copy of its own.</summary>
    /// <returns>The frame.</returns>
    public KeptFrame Keep() => new(number, line, world, [.. body], before, cell, hasCandidates ? candidates[..count] : null, VerdictKind.Agrees);
}
