using System.Numerics;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>
/// One hand-picked estate per class family (docs/indoor.md, "Scene classes"): they round-trip through the corpus
/// format; with ACPHYS_EXAMPLES_DIR set they are also written there (docs/examples/estate-*.json, then rendered).
/// </summary>
public sealed class EstateExamples
{
    /// <summary>Gets the examples: file stem, title, recipe.</summary>
    public static IReadOnlyList<(string Name, string Title, SceneRecipe Recipe)> All { get; } =
    [
        ("estate-ring-frames", "a four-room ring (a loop), every cell in its own frame, yawed and tilted; three doors, one invalid; two L-shaped rooms; in by one door, out by another",
            Recipe(SceneRoute.Through, Plan(EstateLayout.Ring, 4, 3) with { InvalidDoors = 2, LShapes = 0b1100, Tilt = new Vector2(0.012f, -0.008f), EntryDoor = 0, ExitDoor = 1 })),
        ("estate-stairwell", "a branching estate with a storey over room 0 and a stairwell overlapping both: from the stairwell west into room 0 and out",
            Recipe(SceneRoute.Stairwell, Plan(EstateLayout.Branch, 4, 2) with { Storey = true, Stairwell = true })),
        ("estate-corner", "an estate at a four-block corner with three more buildings in the other blocks; the walk starts in the neighbouring block",
            Recipe(SceneRoute.EnterAndBack, Plan(EstateLayout.Row, 3, 2) with { WorldX = (192.0 * 0xA9) - 14, WorldY = (192.0 * 0xB4) - 12, ExtraBuildings = 3, Yaw = 3.5f }, target: 2)),
        ("estate-lead-in", "a lead-in dungeon of the block to the west whose cells lie past its x = 192, out of its exit and in by the estate's west door",
            Recipe(SceneRoute.LeadIn, Plan(EstateLayout.Row, 2, 2) with { WorldX = (192.0 * 0xA9) + 14, Yaw = 0, Lead = 2 })),
        ("estate-vestibule", "a six-room ring with a thin vestibule at the entry door (two portals in one step), an unloaded room in the loop, three spheres",
            Recipe(SceneRoute.Through, Plan(EstateLayout.Ring, 6, 2) with { Vestibule = true, UnloadedRoom = 3 }) with { StepMax = 0.5f }),
        ("estate-terrace", "a terrace of three rooms, every shared wall sealed, each room its own door: outdoors along the doors' facade, within half a radius of the wall, over the two sealed seams",
            Recipe(SceneRoute.Facade, Plan(EstateLayout.Row, 3, 3) with { SealedWalls = 0x7F, EntryDoor = 0, ExitDoor = 1 })),
        ("estate-notch-facade", "a row of three L-shaped rooms with their doors south and their notches north: outdoors along the north facade, where a sphere reaches the rooms' second pieces but not their first",
            Recipe(SceneRoute.Facade, Plan(EstateLayout.Row, 3, 3) with { LShapes = 0b111, EntryDoor = 0 }, target: 1)),
    ];

    [Fact(DisplayName = "Each example estate round-trips through the corpus format and walks the same")]
    public void RoundTrip()
    {
        string? dir = Environment.GetEnvironmentVariable("ACPHYS_EXAMPLES_DIR");
        foreach (var (name, title, recipe) in All)
        {
            var entry = new CorpusEntry { Title = title, FoundBy = "hand", SceneWalk = recipe.Build() };
            string json = CorpusJson.Write(entry);
            var back = CorpusJson.Read(json, name).SceneWalk!;
            Assert.Equal(entry.SceneWalk.Walk.Steps, back.Walk.Steps);
            Assert.Equal(entry.SceneWalk.Scene.Cells.Count, back.Scene.Cells.Count);
            if (dir is not null)
            {
                File.WriteAllText(Path.Combine(dir, name + ".json"), json);
            }
        }
    }

    private static EstatePlan Plan(EstateLayout layout, int rooms, int doors) =>
        new((192.0 * 0xA9) + 60, (192.0 * 0xB4) + 70, layout, rooms, 6, 5, doors, 0, 0.4f, Vector2.Zero, 0b10_01_11_10_01, true, 0b1010_0110);

    private static SceneRecipe Recipe(SceneRoute route, EstatePlan plan, int target = 0) =>
        new(null, null, route, target, 0.5f, false, 0.25f, 1f / 1024, int.MaxValue) { Estate = plan, Spheres = 3, Radius1 = 0.75f, Radius2 = 0.375f };
}
