using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>One timed indoor find_cell_list: a scene, the position's cell, sphere centres in its block frame, the current cell.</summary>
/// <param name="Scene">box-cottage or union-cottage.</param>
/// <param name="Id">A short id, unique within the scene (BenchmarkDotNet's parameter column).</param>
/// <param name="Name">Where the body is.</param>
/// <param name="Description">The scene.</param>
/// <param name="Position">The position's cell (an env cell for queries from indoors, a land cell from outdoors).</param>
/// <param name="Spheres">Sphere centres in the position's block frame.</param>
public sealed record IndoorBenchCase(string Scene, string Id, string Name, Scene Description, CellId Position, Sphere[] Spheres)
{
    /// <summary>Gets how the query is made: a retail movement query (pick on, no visibility filter) unless stated.</summary>
    public CellQueryOptions Options { get; init; } = CellQueryOptions.RetailTransition;

    /// <summary>Gets the case's name as "scene: where".</summary>
    public string Key => $"{Scene}: {Name}";

    /// <summary>Gets the short key, "box/id" or "union/id".</summary>
    public string ShortKey => $"{Scene.Split('-')[0]}/{Id}";
}

/// <summary>
/// The fixed indoor queries both benchmark harnesses time (bench/ and <c>acphys bench</c>): a three-room cottage in
/// block 0xA9B4 at (60, 60) m, 6 × 5 m rooms along +x (the third room crosses the 24 m line x = 72), front door south of
/// room 0, back door north of room 2; and the same cottage with room 0 L-shaped and room 1 stairs. A body of two
/// spheres, r = 0.5 m, at z = 0.6 and 1.3 m.
/// </summary>
public static class IndoorBenchCases
{
    /// <summary>Gets the cottage plan.</summary>
    public static CottagePlan Plan { get; } = new((192.0 * 0xA9) + 60, (192.0 * 0xB4) + 60, 0f, 3, 6f, 5f, 0, true, false);

    /// <summary>Gets the cottage with box rooms.</summary>
    public static Scene BoxCottage { get; } = SceneKit.Cottage(Plan);

    /// <summary>Gets the cottage with an L-shaped room 0 and a stairs room 1 (room 2 a box).</summary>
    public static Scene UnionCottage { get; } = RoomShapes.Shaped(BoxCottage, id => id == Plan.RoomId(0) ? RoomShape.LShape : id == Plan.RoomId(1) ? RoomShape.Stairs : RoomShape.Box);

    /// <summary>Gets every case: both scenes, the union scene's extra "second arm" case.</summary>
    public static IReadOnlyList<IndoorBenchCase> All { get; } = [.. Cases("box-cottage", BoxCottage), .. Cases("union-cottage", UnionCottage)];

    private static IEnumerable<IndoorBenchCase> Cases(string name, Scene scene)
    {
        float w = Plan.Width, d = Plan.Depth;
        IndoorBenchCase Indoors(string id, string what, int room, float x, float y) => new(name, id, what, scene, Plan.RoomId(room), Body(x, y));
        yield return Indoors("room", "inside room 1 (centre)", 1, 1.5f * w, d / 2);
        if (name == "box-cottage")
        {
            yield return Indoors("room-static", "inside room 1, static placement (visibility filter on)", 1, 1.5f * w, d / 2) with { Options = CellQueryOptions.RetailStatic };
        }

        if (name == "union-cottage")
        {
            yield return Indoors("l-arm", "in room 0's second L arm (BSP: outside)", 0, 0.25f * w, 0.85f * d);
        }

        yield return Indoors("front-door", "straddling the front door (exit portal), from room 0", 0, w / 2, 0.2f);
        yield return Indoors("inner-door", "straddling the door to room 1, from room 0", 0, w - 0.2f, d / 2);
        yield return Outdoors(name, scene, "beside", "outdoors next to the building (0.2 m off the wall)", w / 2, -0.7f);
        yield return Outdoors(name, scene, "enter", "outdoors touching the front door (enters room 0)", w / 2, -0.3f);
    }

    private static IndoorBenchCase Outdoors(string name, Scene scene, string id, string what, float x, float y)
    {
        var spheres = Body(x, y);
        var cell = Plan.Block.BlockCell;
        var at = spheres[0].Center;
        if (!LandDefs.AdjustToOutside(ref cell, ref at))
        {
            throw new InvalidOperationException($"bench case '{what}' is off the map");
        }

        // Land cells of one block share its frame: the sphere centres stay as they are.
        return new IndoorBenchCase(name, id, what, scene, cell, spheres);
    }

    private static Sphere[] Body(float x, float y)
    {
        var p = Plan.ToBlock(new Vector3(x, y, 0));
        return [new Sphere(p + new Vector3(0, 0, 0.6f), 0.5f), new Sphere(p + new Vector3(0, 0, 1.3f), 0.5f)];
    }
}
