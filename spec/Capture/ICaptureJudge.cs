namespace AcPhys.Spec.Capture;

/// <summary>
/// Judges frames of one kind against the reference (the outdoor judge, <see cref="OutdoorJudge"/>; an indoor judge over the
/// user's dat files). The checker (<c>CaptureChecker</c>) asks its judges in order and the first that
/// <see cref="Accepts"/> a frame judges it; a frame no judge accepts is not judged. A judge is pure per frame (the checker
/// threads the port's cell), so adding one never changes another's verdicts.
/// </summary>
internal interface ICaptureJudge
{
    /// <summary>Gets the judge's name, for reports.</summary>
    string Name { get; }

    /// <summary>Tests whether this judge judges the frame.</summary>
    /// <param name="query">The frame and its threading.</param>
    /// <returns>True when it does.</returns>
    bool Accepts(in CaptureQuery query);

    /// <summary>Judges the frame: the port's answer against the reference's in the declared mode.</summary>
    /// <param name="query">The frame and its threading.</param>
    /// <returns>The verdict (not judged, with a reason, whenever the printed precision could decide it).</returns>
    FrameVerdict Judge(in CaptureQuery query);
}
