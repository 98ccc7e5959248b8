namespace AcPhys.Formats.Cases;

/// <summary>
/// What a generated scene walk was built from, as the case values see it: the engine's recipe (its generators and
/// shrinker own the concrete type), of which the formats need only the route it takes and its one-line text.
/// </summary>
public interface ISceneRecipe
{
    /// <summary>Gets the route the walk takes.</summary>
    SceneRoute Route { get; }
}
