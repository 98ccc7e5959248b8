using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>What a failure's report said: the replay line (and whether it was seen to reproduce), the written case file and its replay line.</summary>
/// <param name="ReplayLine">The verify command line that replays the failure.</param>
/// <param name="Confirmed">Whether re-running it reproduced the same shrunk case.</param>
/// <param name="CaseFile">The shrunk case written as a corpus file, if it could be.</param>
/// <param name="CaseReplay">The replay command line for that file.</param>
/// <param name="WalkSteps">For a walk: one row per step as the implementation answered it (step, frame, position, containing, cells).</param>
internal sealed record FailureDetail(string ReplayLine, bool Confirmed, string? CaseFile, string? CaseReplay, IReadOnlyList<string[]>? WalkSteps = null);

/// <summary>One finished <c>verify</c> run, as the PR-gate outputs (JUnit XML, markdown summary) see it.</summary>
/// <param name="ImplName">The implementation's name.</param>
/// <param name="Settings">The run's settings.</param>
/// <param name="Results">One result per invariant.</param>
/// <param name="Failures">Replay details of each failed invariant, by ID.</param>
/// <param name="Elapsed">Wall time.</param>
internal sealed record GateRun(string ImplName, VerifySettings Settings, IReadOnlyList<InvariantResult> Results, IReadOnlyDictionary<string, FailureDetail> Failures, TimeSpan Elapsed)
{
    /// <summary>Gets the number of passed invariants.</summary>
    public int Passed => Results.Count(r => r.Status == ResultStatus.Passed);

    /// <summary>Gets the number of failed invariants.</summary>
    public int Failed => Results.Count(r => r.Status == ResultStatus.Failed);

    /// <summary>Gets the number of invariants not tested.</summary>
    public int NotTested => Results.Count(r => r.Status == ResultStatus.NotTested);

    /// <summary>Gets the op names the implementation announced that protocol v1 does not know (its own text, unescaped).</summary>
    public IReadOnlyList<string> UnknownOps { get; init; } = [];

    /// <summary>Gets the number of invariants tested (passed or failed).</summary>
    public int Tested => Passed + Failed;

    /// <summary>Gets a value indicating whether nothing failed but fewer invariants were tested than <c>--min-tested</c>: not a pass.</summary>
    public bool TooFewTested => Failed == 0 && Tested < Settings.MinTested;

    /// <summary>Gets the line that says a run tested too little, and why.</summary>
    public string TooFewTestedText =>
        $"not a pass: {Tested} of {Results.Count} invariants tested, fewer than --min-tested {Settings.MinTested}"
        + (UnknownOps.Count > 0 ? $" (the implementation announced unknown ops: {UnknownOpsText})" : string.Empty);

    /// <summary>Gets the unknown op names, escaped and quoted.</summary>
    public string UnknownOpsText => string.Join(", ", UnknownOps.Take(20).Select(o => "\"" + AcPhys.Formats.Values.InputQuote.Line(o, 64) + "\"")) + (UnknownOps.Count > 20 ? $" and {UnknownOps.Count - 20} more" : string.Empty);

    /// <summary>Gets the seed text of the run: the fixed seed, or the base seed.</summary>
    public string SeedText => Settings.FixedSeed is Seed s ? "seed " + s : "base seed " + Fmt.Decimal(Settings.BaseSeed);
}
