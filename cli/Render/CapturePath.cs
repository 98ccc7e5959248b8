using AcPhys.Spec.Capture;

namespace AcPhys.Cli.Render;

/// <summary>One kept frame of a drawn capture: its number, the centre in world metres, its verdict.</summary>
/// <param name="Number">The frame number.</param>
/// <param name="X">World metres east.</param>
/// <param name="Y">World metres north.</param>
/// <param name="Kind">The frame's verdict.</param>
/// <param name="Pinned">A divergent span's first or last frame: kept whatever the decimation.</param>
internal readonly record struct CapturePoint(long Number, double X, double Y, VerdictKind Kind, bool Pinned);

/// <summary>
/// The decimated path of a capture, built while it streams: every <c>stride</c>-th frame is kept, and when more than
/// <see cref="Cap"/> are kept every other unpinned one is dropped and the stride doubles, so memory stays bounded for
/// any length. A divergent span's first and last frames are pinned (kept), up to <see cref="MaxPinned"/> of them.
/// </summary>
internal sealed class CapturePath
{
    /// <summary>Most unpinned points kept (the drawing stays a few hundred KB).</summary>
    public const int Cap = 3000;

    /// <summary>Most pinned points (two per divergent span, the checker keeps 1,000 spans).</summary>
    public const int MaxPinned = 2 * CaptureReport.MaxSpans;

    private readonly List<CapturePoint> points = [];
    private long stride = 1;
    private long seen;
    private int unpinned;
    private int pinned;
    private CapturePoint? last;
    private bool lastKept;

    /// <summary>Gets the kept points, in frame order.</summary>
    public IReadOnlyList<CapturePoint> Points => points;

    /// <summary>Gets how many frames were offered.</summary>
    public long Frames => seen;

    /// <summary>Offers the next frame.</summary>
    /// <param name="number">Its number.</param>
    /// <param name="x">World metres east.</param>
    /// <param name="y">World metres north.</param>
    /// <param name="kind">Its verdict.</param>
    public void Add(long number, double x, double y, VerdictKind kind)
    {
        bool divergent = kind == VerdictKind.Diverges;
        bool starts = divergent && last is not { Kind: VerdictKind.Diverges };
        if (!divergent && last is { Kind: VerdictKind.Diverges } end && !lastKept)
        {
            Keep(end with { Pinned = pinned < MaxPinned }); // the span's last frame
        }

        var p = new CapturePoint(number, x, y, kind, starts && pinned < MaxPinned);
        lastKept = p.Pinned || seen % stride == 0;
        if (lastKept)
        {
            Keep(p);
        }

        seen++;
        last = p;
    }

    /// <summary>Ends the path: the last frame is kept (pinned when it ends a span).</summary>
    public void Finish()
    {
        if (last is { } p && !lastKept)
        {
            Keep(p with { Pinned = p.Kind == VerdictKind.Diverges && pinned < MaxPinned });
            lastKept = true;
        }
    }

    private void Keep(CapturePoint p)
    {
        points.Add(p);
        if (p.Pinned)
        {
            pinned++;
            return;
        }

        if (++unpinned <= Cap)
        {
            return;
        }

        // Halve: keep pinned points and every other unpinned one.
        int write = 0, u = 0;
        for (int i = 0; i < points.Count; i++)
        {
            if (points[i].Pinned || (u++ % 2) == 0)
            {
                points[write++] = points[i];
            }
        }

        points.RemoveRange(write, points.Count - write);
        unpinned = points.Count(q => !q.Pinned);
        stride *= 2;
    }
}
