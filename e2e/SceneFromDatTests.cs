using System.Text.RegularExpressions;
using AcPhys.E2E.Support;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Dat;
using AcPhys.Formats.Scenes;

namespace AcPhys.E2E;

/// <summary>
/// <c>scene to-dat</c> and <c>scene from-dat</c> as processes: the corpus scene walks written as one dat world come back
/// from it as the same scenes, and replay with the same verdicts; bad input is a clear error with its own exit code.
/// </summary>
public sealed class SceneFromDatTests : IDisposable
{
    private static readonly string[] Files = [.. Directory.GetFiles(Path.Combine(RepoPaths.Corpus, "seeds"), "*.json")
        .Where(f => CorpusJson.ReadFile(f).SceneWalk is not null).Order(StringComparer.Ordinal)];

    private readonly string dir = Directory.CreateTempSubdirectory("acphys-from-dat-").FullName;

    private string Cell => Path.Combine(dir, "cell.dat");

    private string Portal => Path.Combine(dir, "portal.dat");

    [Fact(DisplayName = "DAT-SCENE-EXTRACT (process): every corpus scene walk, written with the others as one dat world, comes back from scene from-dat as the same scene, and replays to the same verdicts")]
    public void CorpusScenesComeBackFromTheFiles()
    {
        WriteWorld();
        Assert.True(Files.Length >= 5, $"{Files.Length} corpus scene walks");
        foreach (var group in Files.GroupBy(f => CorpusJson.ReadFile(f).SceneWalk!.Scene.Blocks[0]))
        {
            string output = Path.Combine(dir, group.Key.Value.ToString("X4") + ".json");
            var run = Acphys.Run(["scene", "from-dat", "--cell", Cell, "--portal", Portal, "--landblock", group.Key.ToString(), "-o", output]);
            Assert.True(run.Exit == 0, run.Err);
            Assert.Matches(@"kept \d+ env cells \(\d+ behind a door", run.Out);
            var got = SceneJson.Read(File.ReadAllText(output), output);
            foreach (string file in group)
            {
                var entry = CorpusJson.ReadFile(file);
                Assert.Empty(DatNormalForm.Differences(DatNormalForm.Of(entry.SceneWalk!.Scene), got, 0));
            }
        }

        // The verdicts: the cottage walk in the scene read from the files holds on the reference and fails under each fault it names.
        var cottage = CorpusJson.ReadFile(Files.Single(f => f.EndsWith("cottage-a9b3-a9b4-through.json", StringComparison.Ordinal)));
        var scene = SceneJson.Read(File.ReadAllText(Path.Combine(dir, "A9B4.json")), "A9B4.json");
        string walkFile = Path.Combine(dir, "cottage-from-dat.json");
        File.WriteAllText(walkFile, CorpusJson.Write(cottage with { SceneWalk = cottage.SceneWalk! with { Scene = scene } }));
        Assert.Equal(0, Acphys.Run(["replay", walkFile]).Exit);
        var faulted = Acphys.Run(["replay", walkFile, "--fault", cottage.Catches[0]]);
        Assert.Equal(1, faulted.Exit);
    }

    [Fact(DisplayName = "scene from-dat: a missing file or a bad landblock is exit 2, a damaged container exit 5 naming the offset, each on one line")]
    public void BadInput()
    {
        WriteWorld();
        string o = Path.Combine(dir, "x.json");
        var badBlock = Acphys.Run(["scene", "from-dat", "--cell", Cell, "--portal", Portal, "--landblock", "0xFFFF", "-o", o]);
        Assert.Equal(2, badBlock.Exit);
        Assert.Contains("--landblock 0xFFFF", badBlock.Err);
        var absent = Acphys.Run(["scene", "from-dat", "--cell", Cell, "--portal", Portal, "--landblock", "0x0101", "-o", o]);
        Assert.Equal(2, absent.Exit);
        Assert.Contains("holds no Landblock record 0x0101FFFF", absent.Err);
        var missing = Acphys.Run(["scene", "from-dat", "--cell", Path.Combine(dir, "nope.dat"), "--portal", Portal, "--landblock", "0xA9B4", "-o", o]);
        Assert.Equal(2, missing.Exit);

        string cut = Path.Combine(dir, "cut.dat");
        File.WriteAllBytes(cut, File.ReadAllBytes(Cell)[..3000]);
        var damaged = Acphys.Run(["scene", "from-dat", "--cell", cut, "--portal", Portal, "--landblock", "0xA9B4", "-o", o]);
        Assert.Equal(5, damaged.Exit);
        Assert.Matches(new Regex("cut.dat: offset 0x148: truncated"), damaged.Err);
        Assert.Single(damaged.Err.Trim().Split('\n'));
        Assert.False(File.Exists(o));
    }

    public void Dispose() => Directory.Delete(dir, recursive: true);

    private void WriteWorld()
    {
        var run = Acphys.Run(["scene", "to-dat", .. Files, "--cell", Cell, "--portal", Portal, "--block-size", "256"]);
        Assert.True(run.Exit == 0, run.Err);
    }
}
