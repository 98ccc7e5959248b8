namespace AcPhys.Spec.Capture;

/// <summary>What a capture check found: the counts, the divergent spans grouped by root cause, and the first divergent frame.</summary>
internal sealed class CaptureReport
{
    /// <summary>The most spans kept (a capture diverging on and off more often is counted past it, in constant memory).</summary>
    public const int MaxSpans = 1000;

    /// <summary>The most spans of one root cause whose frames are kept for the minimiser (the first ones, in frame order).</summary>
    public const int MinimisedSpans = 5;

    /// <summary>The most frames of a span kept for the minimiser (the first divergent frame is the one that matters).</summary>
    public const int MaxWindow = 64;

    /// <summary>Gets or sets the frames read.</summary>
    public long Read { get; set; }

    /// <summary>Gets or sets the frames judged (agreeing or divergent).</summary>
    public long Judged { get; set; }

    /// <summary>Gets or sets the divergent frames.</summary>
    public long Divergent { get; set; }

    /// <summary>Gets or sets the lines that were no frame (comments, blank, an acdream log's other lines).</summary>
    public long Ignored { get; set; }

    /// <summary>Gets or sets how many frames needed the reference at the corners of their precision box.</summary>
    public long CornerChecks { get; set; }

    /// <summary>Gets the frames not judged, by reason, in the order the reasons first occurred.</summary>
    public List<(NotJudgedReason Reason, long Count)> NotJudged { get; } = [];

    /// <summary>Gets the spans (at most <see cref="MaxSpans"/>), in frame order.</summary>
    public List<DivergentSpan> Spans { get; } = [];

    /// <summary>Gets or sets how many spans were counted past <see cref="MaxSpans"/>.</summary>
    public long SpansNotKept { get; set; }

    /// <summary>Gets the first divergent frame's number, or null.</summary>
    public long? FirstDivergence => Spans.Count > 0 ? Spans[0].First.Number : null;

    /// <summary>Gets the number of frames not judged.</summary>
    public long NotJudgedTotal => NotJudged.Sum(n => n.Count);

    /// <summary>Gets the findings: spans grouped by root cause (most frames first), each with its spans in frame order.</summary>
    public IReadOnlyList<CaptureFinding> Findings =>
        [.. Spans.GroupBy(s => s.Cause, StringComparer.Ordinal).Select(g => new CaptureFinding(g.Key, [.. g])).OrderByDescending(f => f.Spans.Sum(s => s.Frames))];

    /// <summary>Counts a frame not judged.</summary>
    /// <param name="reason">Why.</param>
    public void Skip(NotJudgedReason reason)
    {
        for (int i = 0; i < NotJudged.Count; i++)
        {
            if (ReferenceEquals(NotJudged[i].Reason, reason) || NotJudged[i].Reason.Id == reason.Id)
            {
                NotJudged[i] = (NotJudged[i].Reason, NotJudged[i].Count + 1);
                return;
            }
        }

        NotJudged.Add((reason, 1));
    }
}

/// <summary>One root cause of a capture: its spans.</summary>
/// <param name="Cause">The key (<see cref="CaptureCauses"/>).</param>
/// <param name="Spans">The spans, in frame order.</param>
internal sealed record CaptureFinding(string Cause, IReadOnlyList<DivergentSpan> Spans)
{
    /// <summary>Gets the cause's sentence.</summary>
    public string Text => CaptureCauses.Text.TryGetValue(Cause, out string? t) ? t : Cause;
}
