namespace AcPhys.Formats.Cases;

/// <summary>
/// One case of any kind, as runners report it, files store it and the judge (<c>Judges</c>) judges it: a
/// closed set, one subtype per <see cref="CaseKind"/>. C# does not check a switch over a class hierarchy for
/// completeness, so code that handles every kind calls <see cref="Match{T}"/> (one function per kind): a new kind adds a
/// parameter there, and every such place stops compiling until it handles the kind.
/// </summary>
/// <remarks>Immutable.</remarks>
public abstract record AnyCase
{
    private protected AnyCase()
    {
    }

    /// <summary>Gets the kind (the corpus file's <c>kind</c>).</summary>
    public abstract CaseKind Kind { get; }

    /// <summary>Gets the case value itself (a <see cref="LandCase"/>, <see cref="OutdoorCase"/>, <see cref="AcPhys.Formats.Cases.Walk"/>, <see cref="AcPhys.Formats.Cases.SceneWalk"/> or <see cref="PartsCase"/>).</summary>
    public abstract object Value { get; }

    /// <summary>Calls the function of this case's kind (the compiler checks every kind is handled).</summary>
    /// <typeparam name="T">The result type.</typeparam>
    /// <param name="land">For a LandDefs input.</param>
    /// <param name="query">For an open-land query.</param>
    /// <param name="walk">For a walk on open land.</param>
    /// <param name="sceneWalk">For a walk through a scene.</param>
    /// <param name="parts">For a parts query.</param>
    /// <returns>What the function of this kind returns.</returns>
    public abstract T Match<T>(Func<LandQuery, T> land, Func<OutdoorQuery, T> query, Func<OutdoorWalk, T> walk, Func<WalkInScene, T> sceneWalk, Func<PartsQuery, T> parts);

    /// <summary>Wraps a case value of any kind, or returns null for a value that is not a case (a walk of either kind is unwrapped).</summary>
    /// <param name="value">The value.</param>
    /// <returns>The case, or null.</returns>
    public static AnyCase? Of(object? value) => value switch
    {
        AnyCase c => c,
        LandCase land => new LandQuery(land),
        OutdoorCase q => new OutdoorQuery(q),
        Walk w => new OutdoorWalk(w),
        SceneWalk sw => new WalkInScene(sw),
        PartsCase p => new PartsQuery(p),
        AnyWalk any => Of(any.Inner),
        _ => null,
    };

    /// <summary>Wraps a LandDefs input.</summary>
    /// <param name="c">The input.</param>
    public static implicit operator AnyCase(LandCase c) => new LandQuery(c);

    /// <summary>Wraps an open-land query.</summary>
    /// <param name="c">The query.</param>
    public static implicit operator AnyCase(OutdoorCase c) => new OutdoorQuery(c);

    /// <summary>Wraps a walk.</summary>
    /// <param name="c">The walk.</param>
    public static implicit operator AnyCase(Walk c) => new OutdoorWalk(c);

    /// <summary>Wraps a scene walk.</summary>
    /// <param name="c">The scene walk.</param>
    public static implicit operator AnyCase(SceneWalk c) => new WalkInScene(c);

    /// <summary>Wraps a parts query.</summary>
    /// <param name="c">The parts.</param>
    public static implicit operator AnyCase(PartsCase c) => new PartsQuery(c);

    /// <inheritdoc/>
    public sealed override string ToString() => Value.ToString() ?? string.Empty;

    /// <summary>One LandDefs input (kind <c>land</c>).</summary>
    /// <param name="Case">The input.</param>
    public sealed record LandQuery(LandCase Case) : AnyCase
    {
        /// <inheritdoc/>
        public override CaseKind Kind => CaseKind.Land;

        /// <inheritdoc/>
        public override object Value => Case;

        /// <inheritdoc/>
        public override T Match<T>(Func<LandQuery, T> land, Func<OutdoorQuery, T> query, Func<OutdoorWalk, T> walk, Func<WalkInScene, T> sceneWalk, Func<PartsQuery, T> parts) =>
            land(this);
    }

    /// <summary>One open-land query: a cell, spheres, an origin (kind <c>query</c>).</summary>
    /// <param name="Query">The query.</param>
    public sealed record OutdoorQuery(OutdoorCase Query) : AnyCase
    {
        /// <inheritdoc/>
        public override CaseKind Kind => CaseKind.Query;

        /// <inheritdoc/>
        public override object Value => Query;

        /// <inheritdoc/>
        public override T Match<T>(Func<LandQuery, T> land, Func<OutdoorQuery, T> query, Func<OutdoorWalk, T> walk, Func<WalkInScene, T> sceneWalk, Func<PartsQuery, T> parts) =>
            query(this);
    }

    /// <summary>A walk on open land (kind <c>walk</c>).</summary>
    /// <param name="Walk">The walk.</param>
    public sealed record OutdoorWalk(Walk Walk) : AnyCase
    {
        /// <inheritdoc/>
        public override CaseKind Kind => CaseKind.Walk;

        /// <inheritdoc/>
        public override object Value => Walk;

        /// <inheritdoc/>
        public override T Match<T>(Func<LandQuery, T> land, Func<OutdoorQuery, T> query, Func<OutdoorWalk, T> walk, Func<WalkInScene, T> sceneWalk, Func<PartsQuery, T> parts) =>
            walk(this);

        /// <summary>
        /// Gets why the reference cannot judge this walk, or null when it can: a walk starts in a land cell (facts §2:
        /// a land cell's low word is 1–64); from id 0, 0xFFFFFFFF or a malformed id there is no body on the map to follow.
        /// </summary>
        public string? Unjudgeable => Walk.StartCell.IsLand
            ? null
            : $"the walk starts at {Walk.StartCell}, which is not a land cell (low word 0x0001-0x0040): the walk invariants cannot judge a walk from it";
    }

    /// <summary>A walk through a scene (kind <c>scene-walk</c>).</summary>
    /// <param name="Walk">The scene walk.</param>
    public sealed record WalkInScene(SceneWalk Walk) : AnyCase
    {
        /// <inheritdoc/>
        public override CaseKind Kind => CaseKind.SceneWalk;

        /// <inheritdoc/>
        public override object Value => Walk;

        /// <inheritdoc/>
        public override T Match<T>(Func<LandQuery, T> land, Func<OutdoorQuery, T> query, Func<OutdoorWalk, T> walk, Func<WalkInScene, T> sceneWalk, Func<PartsQuery, T> parts) =>
            sceneWalk(this);
    }

    /// <summary>A parts / bounding-box query (kind <c>parts</c>).</summary>
    /// <param name="Parts">The parts.</param>
    public sealed record PartsQuery(PartsCase Parts) : AnyCase
    {
        /// <inheritdoc/>
        public override CaseKind Kind => CaseKind.Parts;

        /// <inheritdoc/>
        public override object Value => Parts;

        /// <inheritdoc/>
        public override T Match<T>(Func<LandQuery, T> land, Func<OutdoorQuery, T> query, Func<OutdoorWalk, T> walk, Func<WalkInScene, T> sceneWalk, Func<PartsQuery, T> parts) =>
            parts(this);
    }
}
