using AcPhys.Formats.Cases;

namespace AcPhys.Formats.Corpus;

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

    /// <summary>Gets the mode the bundled reference ran in when the case was found (field <c>mode</c>), or null for retail.</summary>
    public CaseMode? Mode { get; init; }

    /// <summary>Gets the planted faults this case must expose.</summary>
    public IReadOnlyList<string> Catches { get; init; } = [];

    /// <summary>Gets the LandDefs case, for kind <c>land</c>.</summary>
    public LandCase? Case { get; init; }

    /// <summary>Gets the walk, for kind <c>walk</c>.</summary>
    public Walk? Walk { get; init; }

    /// <summary>Gets the port's recorded answers, one per query of <see cref="Walk"/> (field <c>recorded</c>, a minimised capture), or null.</summary>
    internal IReadOnlyList<RecordedAnswer>? Recorded { get; init; }

    /// <summary>Gets the scene walk, for kind <c>scene-walk</c>.</summary>
    public SceneWalk? SceneWalk { get; init; }

    /// <summary>Gets the parts query, for kind <c>parts</c>.</summary>
    public PartsCase? Parts { get; init; }

    /// <summary>Gets the open-land query, for kind <c>query</c>.</summary>
    public OutdoorCase? Query { get; init; }

    /// <summary>Gets the kind: <c>land</c>, <c>query</c>, <c>walk</c>, <c>scene-walk</c> or <c>parts</c>.</summary>
    public string Kind => KindName(Item.Kind);

    /// <summary>Gets the case the entry holds, whatever its kind.</summary>
    /// <exception cref="InvalidOperationException">The entry holds no case.</exception>
    public AnyCase Item =>
        (AnyCase?)(Parts is { } p ? p : Query is { } q ? q : SceneWalk is { } sw ? sw : Walk is { } w ? w : Case is { } c ? c : null)
        ?? throw new InvalidOperationException("the corpus entry holds no case");

    /// <summary>Returns the file kind of a case kind.</summary>
    /// <param name="kind">The case kind.</param>
    /// <returns><c>land</c>, <c>query</c>, <c>walk</c>, <c>scene-walk</c> or <c>parts</c>.</returns>
    public static string KindName(CaseKind kind) => kind.Pick("land", "query", "walk", "scene-walk", "parts");

    /// <summary>Wraps a failing case of any kind as an entry, or returns null when there is no case.</summary>
    /// <param name="c">The case (an <see cref="AnyCase"/> or a case value of any kind).</param>
    /// <param name="title">Title.</param>
    /// <param name="invariant">Invariant ID.</param>
    /// <param name="foundBy">What found it.</param>
    /// <param name="seed">Seed text.</param>
    /// <returns>The entry, or null.</returns>
    public static CorpusEntry? From(object? c, string title, string? invariant, string foundBy, string? seed = null)
    {
        var header = new CorpusEntry { Title = title, Invariant = invariant, FoundBy = foundBy, Seed = seed };
        return AnyCase.Of(c)?.Match(
            land => header with { Case = land.Case },
            q => header with { Query = q.Query },
            walk => header with { Walk = walk.Walk },
            sw => header with { SceneWalk = sw.Walk },
            parts => header with { Parts = parts.Parts });
    }
}
