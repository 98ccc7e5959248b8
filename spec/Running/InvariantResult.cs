using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Running;

/// <summary>How one invariant fared in a run.</summary>
public enum ResultStatus
{
    /// <summary>Every case held.</summary>
    Passed,

    /// <summary>A case violated it.</summary>
    Failed,

    /// <summary>The implementation lacks an operation it needs.</summary>
    NotTested,
}

/// <summary>The result of running one invariant against one implementation.</summary>
public sealed record InvariantResult
{
    /// <summary>Gets the invariant.</summary>
    public required Invariant Invariant { get; init; }

    /// <summary>Gets the verdict.</summary>
    public required ResultStatus Status { get; init; }

    /// <summary>Gets the number of generated cases checked (before any shrinking).</summary>
    public int Cases { get; init; }

    /// <summary>Gets how many of them the invariant applied to (not vacuous).</summary>
    public int Applicable { get; init; }

    /// <summary>Gets the exhaustive cases checked, when the profile sweeps a finite domain this invariant covers.</summary>
    public long ExhaustiveCases { get; init; }

    /// <summary>Gets how often each boundary class was hit.</summary>
    public IReadOnlyDictionary<string, int> Classes { get; init; } = new Dictionary<string, int>();

    /// <summary>Gets the seed the generated cases came from.</summary>
    public Seed Seed { get; init; }

    /// <summary>Gets the shrunk violation, when failed.</summary>
    public Violation? Violation { get; init; }

    /// <summary>Gets the violation as first found, before shrinking.</summary>
    public Violation? Original { get; init; }

    /// <summary>Gets the failure class of <see cref="Violation"/>: the primary boundary class of its shrunk case.</summary>
    public string? FailureClass { get; init; }

    /// <summary>
    /// Gets the further failures of other classes found after the first, within the same case budget, each shrunk
    /// (the run keeps searching, counting a violation of a class already reported as seen, not as a new failure).
    /// </summary>
    public IReadOnlyList<ClassFailure> MoreFailures { get; init; } = [];

    /// <summary>Gets the seed and size that replay the failing case.</summary>
    public Seed? Replay { get; init; }

    /// <summary>Gets why the invariant was not tested.</summary>
    public string? NotTestedReason { get; init; }

    /// <summary>Gets the time from the start of the run to the first violating case (before shrinking), when failed by a generated case.</summary>
    public TimeSpan? TimeToFailure { get; init; }

    /// <summary>Gets the time spent.</summary>
    public TimeSpan Elapsed { get; init; }
}

/// <summary>One more failure class of an invariant: its shrunk violation and the seed that finds it.</summary>
/// <param name="Class">The failure class (primary boundary class of the shrunk case).</param>
/// <param name="Violation">The shrunk violation.</param>
/// <param name="Replay">The seed of the search that found it (with the classes before it excluded).</param>
public sealed record ClassFailure(string Class, Violation Violation, Seed Replay);
