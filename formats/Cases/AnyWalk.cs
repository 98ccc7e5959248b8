namespace AcPhys.Formats.Cases;

/// <summary>A walk of either kind: on open land (<see cref="Walk"/>) or in a scene (<see cref="SceneWalk"/>); exactly one is set.</summary>
/// <param name="Outdoor">The open-land walk, or null.</param>
/// <param name="Indoor">The scene walk, or null.</param>
public sealed record AnyWalk(Walk? Outdoor, SceneWalk? Indoor)
{
    /// <summary>Gets the walk itself (a <see cref="Walk"/> or a <see cref="SceneWalk"/>), for corpus files.</summary>
    public object Inner => (object?)Outdoor ?? Indoor!;

    /// <inheritdoc/>
    public override string ToString() => Inner.ToString()!;
}
