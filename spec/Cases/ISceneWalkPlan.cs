using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// A scene-walk plan that builds its whole case (issue 41: side-by-side interiors, exact bounds in the cell frame):
/// the generator, classes and shrinking live with the plan (spec/Generators), so the recipe only carries it.
/// </summary>
public interface ISceneWalkPlan
{
    /// <summary>Gets the shape class of the scene, for distributions.</summary>
    string Shape { get; }

    /// <summary>Builds the case.</summary>
    /// <param name="recipe">The recipe carrying this plan (its Take and body apply).</param>
    /// <returns>The scene walk.</returns>
    SceneWalk Build(SceneRecipe recipe);

    /// <summary>Returns the plan's case classes.</summary>
    /// <returns>Tags.</returns>
    IEnumerable<string> Classes();

    /// <summary>Returns simpler plans that keep what the plan shows.</summary>
    /// <returns>Candidates.</returns>
    IEnumerable<ISceneWalkPlan> Shrink();
}
