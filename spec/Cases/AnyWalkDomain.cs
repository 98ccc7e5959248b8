using AcPhys.Formats.Cases;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Cases;

/// <summary>The domain of both kinds of walk: open-land walks (one part in three) and scene walks, each with its own shrinker and classes.</summary>
internal sealed class AnyWalkDomain : ICaseDomain<AnyWalk>
{
    /// <summary>Gets the instance.</summary>
    public static AnyWalkDomain Instance { get; } = new();

    /// <inheritdoc/>
    public Arbitrary<AnyWalk> Arbitrary { get; } = Arb.From(
        Gen.Frequency(
            (1, WalkGens.Arbitrary.Generator.Select(w => new AnyWalk(w, null))),
            (2, SceneGens.Arbitrary.Generator.Select(w => new AnyWalk(null, w)))),
        Shrink);

    /// <inheritdoc/>
    public IEnumerable<string> Classes(AnyWalk c) => c.Outdoor is { } w ? WalkDomain.Instance.Classes(w) : SceneDomain.Instance.Classes(c.Indoor!);

    /// <inheritdoc/>
    public string Primary(AnyWalk c) => c.Outdoor is { } w ? WalkDomain.Instance.Primary(w) : SceneDomain.Instance.Primary(c.Indoor!);

    private static IEnumerable<AnyWalk> Shrink(AnyWalk c) => c.Outdoor is { } w
        ? WalkGens.Arbitrary.Shrinker(w).Select(x => new AnyWalk(x, null))
        : SceneGens.Arbitrary.Shrinker(c.Indoor!).Select(x => new AnyWalk(null, x));
}
