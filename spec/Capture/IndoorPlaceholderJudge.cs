namespace AcPhys.Spec.Capture;

/// <summary>
/// The frames of env cells while no indoor judge is given a scene: each is not judged, with the reason
/// (<see cref="NotJudgedReason.IndoorNoDats"/>). An indoor judge over the user's dat files goes before it in the checker's list.
/// </summary>
internal sealed class IndoorPlaceholderJudge : ICaptureJudge
{
    /// <summary>Gets the shared instance.</summary>
    public static IndoorPlaceholderJudge Instance { get; } = new();

    /// <inheritdoc/>
    public string Name => "indoor (no dat files)";

    /// <inheritdoc/>
    public bool Accepts(in CaptureQuery query) => query.IsIndoor;

    /// <inheritdoc/>
    public FrameVerdict Judge(in CaptureQuery query) => FrameVerdict.Skip(NotJudgedReason.IndoorNoDats);
}
