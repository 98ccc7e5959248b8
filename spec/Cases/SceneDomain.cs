using AcPhys.Formats.Cases;
using AcPhys.Spec.Generators;
using FsCheck;

namespace AcPhys.Spec.Cases;

/// <summary>The scene-walk case domain.</summary>
public sealed class SceneDomain : ICaseDomain<SceneWalk>
{
    /// <summary>Gets the instance.</summary>
    public static SceneDomain Instance { get; } = new();

    /// <inheritdoc/>
    public Arbitrary<SceneWalk> Arbitrary => SceneGens.Arbitrary;

    /// <inheritdoc/>
    public IEnumerable<string> Classes(SceneWalk w)
    {
        if (w.Recipe is not SceneRecipe r)
        {
            yield return "scene:stored";
            yield break;
        }

        yield return "scene:" + r.Shape;
        yield return "route:" + r.Route;
        foreach (var tag in CornerClasses.Of(r))
        {
            yield return tag;
        }

        foreach (var tag in r.Plan?.Classes() ?? [])
        {
            yield return tag;
        }

        foreach (var tag in (r.Plan as SideBySidePlan)?.WalkClasses(w) ?? [])
        {
            yield return tag;
        }

        if (r.Hub is { } hub)
        {
            foreach (var tag in HubClasses.Of(hub, w))
            {
                yield return tag;
            }

            yield break;
        }

        if (r.Estate is not null)
        {
            foreach (var tag in EstateClasses.Of(r, w))
            {
                yield return tag;
            }

            yield break;
        }

        if (r.Cottage is { } c)
        {
            var a = c.ToBlock(System.Numerics.Vector3.Zero);
            var b = c.ToBlock(new System.Numerics.Vector3(c.Rooms * c.Width, c.Depth, 0));
            if (Math.Floor(a.X / 192) != Math.Floor(b.X / 192) || Math.Floor(a.Y / 192) != Math.Floor(b.Y / 192))
            {
                yield return "place:across-block-line";
            }

            if (c.WorldX < 192 || c.WorldX > 192 * 0xFE)
            {
                yield return "place:map-edge";
            }

            if (!c.LoadNeighbours)
            {
                yield return "place:unloaded-neighbours";
            }

            if (c.Closet)
            {
                yield return "cell:portal-less"; // facts §5.5, §7 #13: a sealed closet, entered by building entry only
            }

            if (c.Yaw % (MathF.PI / 2) != 0)
            {
                yield return "yaw:oblique";
            }
        }

        if (r.Dungeon is { Unloaded: > 0 })
        {
            yield return "dungeon:unloaded-tail";
        }
    }

    /// <inheritdoc/>
    public string Primary(SceneWalk w) => Classes(w).Skip(1).FirstOrDefault() ?? "scene:stored";
}
