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

    /// <summary>Gets the LandDefs case, for kind <c>land</c>.</summary>
    public LandCase? Case { get; init; }

    /// <summary>Gets the walk, for kind <c>walk</c>.</summary>
    public Walk? Walk { get; init; }

    /// <summary>Gets the scene walk, for kind <c>scene-walk</c>.</summary>
    public SceneWalk? SceneWalk { get; init; }

    /// <summary>Gets the parts query, for kind <c>parts</c>.</summary>
    public PartsCase? Parts { get; init; }

    /// <summary>Gets the kind: <c>land</c>, <c>walk</c>, <c>scene-walk</c> or <c>parts</c>.</summary>
    public string Kind => Parts is not null ? "parts" : SceneWalk is not null ? "scene-walk" : Walk is null ? "land" : "walk";

    /// <summary>Wraps a failing case of any supported type as an entry, or returns null for an unsupported type.</summary>
    /// <param name="c">A LandCase, Walk, SceneWalk, PartsCase or OutdoorCase (stored as a walk with no steps; with no spheres, not at all).</param>
    /// <param name="title">Title.</param>
    /// <param name="invariant">Invariant ID.</param>
    /// <param name="foundBy">What found it.</param>
    /// <param name="seed">Seed text.</param>
    /// <returns>The entry, or null.</returns>
    public static CorpusEntry? From(object? c, string title, string? invariant, string foundBy, string? seed = null) => c switch
    {
        AnyWalk any => From(any.Inner, title, invariant, foundBy, seed),
        LandCase land => new CorpusEntry { Title = title, Invariant = invariant, FoundBy = foundBy, Seed = seed, Case = land },
        Walk walk => new CorpusEntry { Title = title, Invariant = invariant, FoundBy = foundBy, Seed = seed, Walk = walk },
        SceneWalk sw => new CorpusEntry { Title = title, Invariant = invariant, FoundBy = foundBy, Seed = seed, SceneWalk = sw },
        PartsCase parts => new CorpusEntry { Title = title, Invariant = invariant, FoundBy = foundBy, Seed = seed, Parts = parts },
        // A query with no spheres has no walk form (a walk judges sphere 0; facts §3.3 step 3 reads the origin
        // instead): it is reported, not stored.
        OutdoorCase { Spheres.Count: 0 } => null,
        OutdoorCase q => new CorpusEntry
        {
            Title = title,
            Invariant = invariant,
            FoundBy = foundBy,
            Seed = seed,
            Walk = new Walk(q.Cell, System.Numerics.Vector3.Zero, q.Spheres.Select(s => new BodySphere(s.Center, s.Radius)).ToArray(), []),
        },
        _ => null,
    };
}
