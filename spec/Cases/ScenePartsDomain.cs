using AcPhys.Formats.Cases;
using FsCheck;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The scene-walk case domain of the parts invariants indoors: the scene walks' generator and shrinker (the same cases
/// under the same seed), their classes and the classes of the parts queries they stand for (<see cref="ScenePartsClasses"/>).
/// </summary>
internal sealed class ScenePartsDomain : ICaseDomain<SceneWalk>
{
    /// <summary>Gets the instance.</summary>
    public static ScenePartsDomain Instance { get; } = new();

    /// <inheritdoc/>
    public Arbitrary<SceneWalk> Arbitrary => SceneDomain.Instance.Arbitrary;

    /// <inheritdoc/>
    public IEnumerable<string> Classes(SceneWalk w) => SceneDomain.Instance.Classes(w).Concat(ScenePartsClasses.Of(w));

    /// <inheritdoc/>
    public string Primary(SceneWalk w) => SceneDomain.Instance.Primary(w);
}
