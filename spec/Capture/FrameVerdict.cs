using AcPhys.Core;

namespace AcPhys.Spec.Capture;

/// <summary>What a judge said about one frame.</summary>
internal enum VerdictKind
{
    /// <summary>The port's answer is the reference's.</summary>
    Agrees,

    /// <summary>The port's answer differs from the reference's, and the printed precision cannot explain it.</summary>
    Diverges,

    /// <summary>Not judged (<see cref="FrameVerdict.Reason"/> says why): never a divergence.</summary>
    NotJudged,
}

/// <summary>Which part of the port's answer differs.</summary>
internal enum DivergenceKind
{
    /// <summary>No difference.</summary>
    None,

    /// <summary>The port's cell after the frame is not the reference's containing cell.</summary>
    Cell,

    /// <summary>The candidate list holds other cells than the reference's.</summary>
    CandidateContent,

    /// <summary>The candidate list holds the reference's cells in another order (insertion order is pinned: FIND-CELL-CONFORMANCE).</summary>
    CandidateOrder,
}

/// <summary>
/// A judge's verdict on one frame.
/// </summary>
/// <param name="Kind">Agrees, diverges or not judged.</param>
/// <param name="Reference">The reference's containing cell (after the frame), or <see cref="CellId.None"/> when not judged or none.</param>
/// <param name="Divergence">What differs (<see cref="DivergenceKind.None"/> unless <see cref="VerdictKind.Diverges"/>).</param>
/// <param name="Reason">Why the frame was not judged (for <see cref="VerdictKind.NotJudged"/>), else null.</param>
internal readonly record struct FrameVerdict(VerdictKind Kind, CellId Reference, DivergenceKind Divergence, NotJudgedReason? Reason)
{
    /// <summary>Gets the reference's candidates when the candidate list diverges (allocated only then), else null.</summary>
    public IReadOnlyList<CellId>? ReferenceCells { get; init; }

    /// <summary>Returns an agreeing verdict.</summary>
    /// <param name="reference">The reference's containing cell.</param>
    /// <returns>The verdict.</returns>
    public static FrameVerdict Agree(CellId reference) => new(VerdictKind.Agrees, reference, DivergenceKind.None, null);

    /// <summary>Returns a not-judged verdict.</summary>
    /// <param name="reason">Why.</param>
    /// <returns>The verdict.</returns>
    public static FrameVerdict Skip(NotJudgedReason reason) => new(VerdictKind.NotJudged, CellId.None, DivergenceKind.None, reason);

    /// <summary>Returns a divergent verdict.</summary>
    /// <param name="reference">The reference's containing cell.</param>
    /// <param name="what">What differs.</param>
    /// <param name="cells">The reference's candidates, when they differ.</param>
    /// <returns>The verdict.</returns>
    public static FrameVerdict Diverge(CellId reference, DivergenceKind what, IReadOnlyList<CellId>? cells = null) =>
        new(VerdictKind.Diverges, reference, what, null) { ReferenceCells = cells };
}
