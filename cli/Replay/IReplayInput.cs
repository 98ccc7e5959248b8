namespace AcPhys.Cli.Replay;

/// <summary>
/// One kind of input file <c>acphys replay</c> understands, chosen by the file's JSON <c>kind</c> field
/// (<see cref="KindReplay"/>: one per case kind).
/// </summary>
internal interface IReplayInput
{
    /// <summary>Gets the value of the <c>kind</c> field this input reads.</summary>
    string Kind { get; }

    /// <summary>Gets a short description, for help and messages.</summary>
    string Description { get; }

    /// <summary>Reads the file, checks it against the target and prints the report.</summary>
    /// <param name="path">The file.</param>
    /// <param name="target">What to check against.</param>
    /// <returns>The exit code: 0 all held, 1 something was violated, 2 the input is unusable.</returns>
    int Replay(string path, ReplayTarget target);
}
