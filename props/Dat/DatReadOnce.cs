using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats;
using AcPhys.Formats.Scenes;
using Xunit.Abstractions;

namespace AcPhys.Props.Dat;

/// <summary>
/// Records are read once (issue #26): the record reader checks the scene it builds with <see cref="SceneRules"/>
/// instead of writing it as scene JSON and reading that back, and gives the same scene and the same refusals.
/// </summary>
public sealed class DatReadOnce(ITestOutputHelper output)
{
    private const int Seed = 0x26B;

    [Fact(DisplayName = "Scenes read from records equal today's path, read(write(scene JSON)), to the byte (1,000 generated and 1,000 multi-piece scenes)")]
    public void RecordsGiveTheSceneTheJsonRoundTripGave()
    {
        int scenes = 0;
        foreach (var scene in DatTestSupport.Generated(1000, 0xDA7C).Concat(DatTestSupport.MultiPiece(1000, 0xDA7D)))
        {
            var (_, back) = DatTestSupport.RoundTrip(scene);
            var before = SceneJson.Read(SceneJson.Write(back), "records"); // what the reader returned before issue #26
            Assert.True(SceneJson.Write(back) == SceneJson.Write(before), $"{scene}: the scene read from records differs from its scene-JSON round trip");
            Assert.Equal(before.UnloadedCells, back.UnloadedCells);
            Assert.Equal(before.UnloadedBlocks, back.UnloadedBlocks);
            scenes++;
        }

        output.WriteLine($"{scenes} scenes: the records give the scene the JSON round trip gave");
    }

    [Fact(DisplayName = "SceneRules.Check refuses a broken scene with the scene-JSON reader's first message, and accepts what it accepts (4,000 mutated scenes, seed 0x26B)")]
    public void CheckRefusesAsTheSceneReaderDoes()
    {
        var random = new Random(Seed);
        var scenes = DatTestSupport.Generated(200, 0xDA7E).Concat(DatTestSupport.MultiPiece(200, 0xDA7F)).ToArray();
        int refused = 0;
        for (int i = 0; i < 4000; i++)
        {
            var scene = scenes[random.Next(scenes.Length)];
            var names = new List<string>();
            for (int m = random.Next(1, 3); m > 0; m--)
            {
                var (name, mutate) = Mutations[random.Next(Mutations.Length)];
                scene = mutate(scene, random);
                names.Add(name);
            }

            string json = Outcome(() => SceneJson.Read(SceneJson.Write(scene), "records"));
            string check = Outcome(() => new SceneRules("records").Check(scene, "$"));
            Assert.True(json == check, $"seed {Seed}, scene {i} ({string.Join(" + ", names)}): scene JSON reader {json}; SceneRules.Check {check}; scene {scene}");
            refused += json.StartsWith("refused", StringComparison.Ordinal) ? 1 : 0;
        }

        output.WriteLine($"4000 mutated scenes: {refused} refused, every one alike");
        Assert.True(refused > 1000, $"the mutations must break scenes: only {refused} of 4000 refused");
    }

    private static readonly (string Name, Func<Scene, Random, Scene> Mutate)[] Mutations =
    [
        ("non-unit rotation", (s, r) => WithCell(s, r, c => c with { Rotation = Quaternion.Normalize(c.Rotation) * 1.01f })),
        ("portal to an unknown cell", (s, r) => WithPortal(s, r, p => p with { Other = 0xFFF0 })),
        ("portal to a land cell", (s, r) => WithPortal(s, r, p => p with { Other = 0x0031 })),
        ("portal to itself", (s, r) => WithCell(s, r, c => c.Portals.Count == 0 ? c : c with { Portals = [c.Portals[0] with { Other = c.Id.Low }, .. c.Portals.Skip(1)] })),
        ("unknown visible cell", (s, r) => WithCell(s, r, c => c with { Visible = [.. c.Visible, c.Id.WithLow(0xFFF1)] })),
        ("visible land cell", (s, r) => WithCell(s, r, c => c with { Visible = [c.Id.WithLow(0x0001), .. c.Visible] })),
        ("non-env cell id", (s, r) => WithCell(s, r, c => c with { Id = c.Id.WithLow(0x0040) })),
        ("cell in an undeclared block", (s, r) => WithCell(s, r, c => c with { Id = new CellId((byte)(c.Id.BlockX ^ 0x40), c.Id.BlockY, c.Id.Low) })),
        ("duplicate cell", (s, r) => s.Cells.Count == 0 ? s : s with { Cells = [.. s.Cells, s.Cells[r.Next(s.Cells.Count)]] }),
        ("duplicate block", (s, r) => s with { Blocks = [.. s.Blocks, s.Blocks[r.Next(s.Blocks.Count)]] }),
        ("off-map block", (s, r) => s with { UnloadedBlocks = [.. s.UnloadedBlocks, new LandblockId(0xFF, 3)] }),
        ("non-env unloaded cell", (s, r) => s with { UnloadedCells = [.. s.UnloadedCells, s.Blocks[0].BlockCell.WithLow(0x0007)] }),
        ("unloaded cell that is loaded", (s, r) => s.Cells.Count == 0 ? s : s with { UnloadedCells = [s.Cells[r.Next(s.Cells.Count)].Id, .. s.UnloadedCells] }),
        ("degenerate box", (s, r) => WithCell(s, r, c => c with { Pieces = [.. c.Pieces.Select(p => p.Box is { } b ? ScenePiece.FromBox(b.Max, b.Max) : p)] })),
        ("degenerate plane", (s, r) => WithCell(s, r, c => c with { Pieces = [.. c.Pieces.Select(p => p.Planes is { Count: > 0 } ps ? new ScenePiece(null, [new CellPlane(Vector3.Zero, 1), .. ps.Skip(1)]) : p)] })),
        ("no pieces", (s, r) => WithCell(s, r, c => c with { Pieces = [] })),
        ("building portal index out of range", (s, r) => WithBuilding(s, r, b => b with { Portals = [.. b.Portals.Select(p => p with { Portal = 99 })] })),
        ("building portal to an unknown cell", (s, r) => WithBuilding(s, r, b => b with { Portals = [new SceneBldPortal(0xFFF2, 0), .. b.Portals] })),
        ("building in an undeclared block", (s, r) => WithBuilding(s, r, b => b with { Block = new LandblockId((byte)(b.Block.X ^ 0x40), b.Block.Y) })),
        ("second building in a land cell", (s, r) => s.Buildings.Count == 0 ? s : s with { Buildings = [.. s.Buildings, s.Buildings[r.Next(s.Buildings.Count)]] }),
    ];

    private static string Outcome(Func<Scene> read)
    {
        try
        {
            return "accepted " + SceneJson.Write(read());
        }
        catch (InputFormatException e)
        {
            return "refused " + e.Message;
        }
    }

    private static Scene WithCell(Scene s, Random r, Func<SceneCell, SceneCell> change)
    {
        if (s.Cells.Count == 0)
        {
            return s;
        }

        int i = r.Next(s.Cells.Count);
        return s with { Cells = [.. s.Cells.Select((c, k) => k == i ? change(c) : c)] };
    }

    private static Scene WithPortal(Scene s, Random r, Func<ScenePortal, ScenePortal> change) =>
        WithCell(s, r, c => c.Portals.Count == 0 ? c : c with { Portals = [.. c.Portals.Select((p, k) => k == c.Portals.Count - 1 ? change(p) : p)] });

    private static Scene WithBuilding(Scene s, Random r, Func<SceneBuilding, SceneBuilding> change)
    {
        if (s.Buildings.Count == 0)
        {
            return s;
        }

        int i = r.Next(s.Buildings.Count);
        return s with { Buildings = [.. s.Buildings.Select((b, k) => k == i ? change(b) : b)] };
    }
}
