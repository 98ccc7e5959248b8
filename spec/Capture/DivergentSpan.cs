using System.Globalization;
using AcPhys.Core;

namespace AcPhys.Spec.Capture;

/// <summary>
/// A run of consecutive divergent frames with one cause (frames not judged inside it keep it open; an agreeing frame or
/// another cause ends it): one finding of a capture.
/// </summary>
internal sealed class DivergentSpan
{
    /// <summary>Initializes a new instance of the <see cref="DivergentSpan"/> class at its first frame.</summary>
    /// <param name="cause">The root-cause key.</param>
    /// <param name="first">The first divergent frame.</param>
    /// <param name="verdict">Its verdict.</param>
    public DivergentSpan(string cause, KeptFrame first, FrameVerdict verdict)
    {
        Cause = cause;
        First = first;
        PortCell = first.Cell;
        ReferenceCell = verdict.Reference;
        Divergence = verdict.Divergence;
        ReferenceCells = verdict.ReferenceCells;
        LastNumber = first.Number;
        LastReference = verdict.Reference;
        Frames = 1;
    }

    /// <summary>Gets the root-cause key.</summary>
    public string Cause { get; }

    /// <summary>Gets the first divergent frame.</summary>
    public KeptFrame First { get; }

    /// <summary>Gets the port's cell at the first frame.</summary>
    public CellId PortCell { get; }

    /// <summary>Gets the reference's cell at the first frame.</summary>
    public CellId ReferenceCell { get; }

    /// <summary>Gets the reference's cell at the last divergent frame.</summary>
    public CellId LastReference { get; private set; }

    /// <summary>Gets what differs.</summary>
    public DivergenceKind Divergence { get; }

    /// <summary>Gets the reference's candidates at the first frame when they differ.</summary>
    public IReadOnlyList<CellId>? ReferenceCells { get; }

    /// <summary>Gets the last divergent frame's number.</summary>
    public long LastNumber { get; private set; }

    /// <summary>Gets how many frames the span covers, first to last (not-judged frames inside included).</summary>
    public long Frames { get; private set; }

    /// <summary>Gets the distance sphere 0's centre moved from the first to the last divergent frame, metres.</summary>
    public double Moved { get; private set; }

    /// <summary>Gets the frames kept for the minimiser: the last agreed frame before the span (when any) and the span's first frames.</summary>
    public List<KeptFrame> Window { get; } = [];

    /// <summary>Extends the span to a divergent frame.</summary>
    /// <param name="number">Its number.</param>
    /// <param name="frames">Frames read since the span's first frame, inclusive.</param>
    /// <param name="worldX">Its world x.</param>
    /// <param name="worldY">Its world y.</param>
    /// <param name="reference">The reference's cell there.</param>
    public void Extend(long number, long frames, double worldX, double worldY, CellId reference)
    {
        LastNumber = number;
        Frames = frames;
        LastReference = reference;
        Moved = Math.Sqrt(((worldX - First.WorldX) * (worldX - First.WorldX)) + ((worldY - First.WorldY) * (worldY - First.WorldY)));
    }

    /// <summary>Returns the span in one sentence, e.g. "cell 0xA9B40031 held for 1,043 frames while the centre moved 20.9 m into 0xA9B3".</summary>
    /// <returns>The text.</returns>
    public string Describe()
    {
        string frames = Frames == 1 ? "1 frame" : string.Create(CultureInfo.InvariantCulture, $"{Frames:N0} frames");
        string moved = string.Create(CultureInfo.InvariantCulture, $"{Moved:0.0} m");
        string into = LastReference.Landblock != PortCell.Landblock ? LastReference.Landblock.ToString() : LastReference.ToString();
        return Divergence switch
        {
            DivergenceKind.Cell when Cause.StartsWith("cell-held", StringComparison.Ordinal) =>
                $"cell {PortCell} held for {frames} while the centre moved {moved} into {into}",
            DivergenceKind.Cell => $"cell {Cell(PortCell)} where the reference has {ReferenceCell}, for {frames} (the centre moved {moved})",
            _ => $"candidates [{string.Join(", ", First.Candidates ?? [])}] where the reference has [{string.Join(", ", ReferenceCells ?? [])}]{(Divergence == DivergenceKind.CandidateOrder ? " (same cells, another order)" : string.Empty)}, for {frames} (the centre moved {moved})",
        };
    }

    private static string Cell(CellId id) => id.IsNone ? "none" : id.ToString();
}
