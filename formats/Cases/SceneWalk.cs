using AcPhys.Contract;

namespace AcPhys.Formats.Cases;

/// <summary>
/// A walk in a scene: the scene, the walk (start cell may be an env cell), and — for generated cases — the recipe it
/// was built from, which the shrinker simplifies (fewer rooms, no rotation, fewer steps) and rebuilds.
/// </summary>
/// <param name="Scene">The scene.</param>
/// <param name="Walk">The walk; its steps move the body horizontally.</param>
public sealed record SceneWalk(Scene Scene, Walk Walk)
{
    private readonly SceneRoute? route;

    /// <summary>Gets the recipe the case was built from, or null for a stored case.</summary>
    public ISceneRecipe? Recipe { get; init; }

    /// <summary>
    /// Gets the route the walk takes: the recipe's, or the one a stored file names (a file keeps no recipe, but ENTER-EXIT
    /// judges only walks that go in and come back, so the file keeps that much and a failure of it replays).
    /// </summary>
    public SceneRoute? Route
    {
        get => route ?? Recipe?.Route;
        init => route = value;
    }

    /// <summary>Gets the state size, for reports of shrunk cases: rooms (env cells, loaded or not), portals, steps.</summary>
    public string Size => $"{Scene.Cells.Count + Scene.UnloadedCells.Count} rooms, {Scene.PortalCount} portals, {Walk.Steps.Count} steps";

    /// <summary>Formats the case on one line.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => $"{Recipe?.ToString() ?? "stored"}; {Scene}; walk {Walk}";
}
