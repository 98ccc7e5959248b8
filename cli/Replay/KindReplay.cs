namespace AcPhys.Cli.Replay;

/// <summary>One kind of stored case <c>replay</c> reads; every kind is judged by the library (<see cref="Spec.Judging.Judges"/>) and printed by <see cref="ReplayPrinter"/>.</summary>
/// <param name="Kind">The file's <c>kind</c>.</param>
/// <param name="Description">A short description, for help and messages.</param>
internal sealed record KindReplay(string Kind, string Description) : IReplayInput
{
    /// <inheritdoc/>
    public int Replay(string path, ReplayTarget target) => ReplayPrinter.Replay(CaseFiles.Read(path), path, target);
}
