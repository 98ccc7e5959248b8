using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Corpus;

/// <summary>
/// One stored case: a seed or a minimised regression. Replayed on every test run: every invariant must hold on it
/// against the reference core, and every fault it names in <see cref="Catches"/> must be caught by it.
/// </summary>
public sealed record CorpusEntry
{
    /// <summary>The current format version.</summary>
    public const int CurrentVersion = 1;

    /// <summary>Gets a one-line title.</summary>
    public required string Title { get; init; }

    /// <summary>Gets the invariant this case guards, or null for a plain seed.</summary>
    public string? Invariant { get; init; }

    /// <summary>Gets what found it: <c>hand</c>, <c>props</c>, <c>fuzz</c> or <c>spec</c>.</summary>
    public required string FoundBy { get; init; }

    /// <summary>Gets the seed that found it, when generated.</summary>
    public string? Seed { get; init; }

    /// <summary>Gets the planted faults this case must expose.</summary>
    public IReadOnlyList<string> Catches { get; init; } = [];

    /// <summary>Gets the case.</summary>
    public required LandCase Case { get; init; }
}
