using AcPhys.Formats.Cases;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The case domain of PARTS-BUILDING-ENTRY: the parts scene walks (<see cref="ScenePartsDomain"/>) of scenes with at
/// least one building, since a walk with no building door (a dungeon) leaves the invariant nothing to judge (facts
/// §5.3: only a land cell's building leads indoors). Its generator redraws a scene without a building and its shrinker
/// keeps a building; the classes are the parts domain's.
/// </summary>
internal sealed class ScenePartsBuildingDomain : ICaseDomain<SceneWalk>
{
    /// <summary>Gets the instance.</summary>
    public static ScenePartsBuildingDomain Instance { get; } = new();

    /// <inheritdoc/>
    public Arbitrary<SceneWalk> Arbitrary { get; } = Arb.From(
        SceneGens.Recipes.Select(r => r.Build()).Where(HasBuilding),
        w => SceneShrinker.Shrink(w).Where(HasBuilding));

    /// <inheritdoc/>
    public IEnumerable<string> Classes(SceneWalk w) => ScenePartsDomain.Instance.Classes(w);

    /// <inheritdoc/>
    public string Primary(SceneWalk w) => ScenePartsDomain.Instance.Primary(w);

    private static bool HasBuilding(SceneWalk w) => w.Scene.Buildings.Count > 0;
}
