using AcPhys.E2E.Support;
using AcPhys.Formats.Corpus;

namespace AcPhys.E2E;

/// <summary>
/// <c>verify --cell-dat --portal-dat</c> as a process: the dat-world gate passes on the reference, a planted indoor fault
/// fails it with the landblock and cell in the finding, and the printed replay line reloads the same scene from the same
/// files and fails the same way.
/// </summary>
public sealed class VerifyDatWorldTests : IDisposable
{
    private readonly string dir = Directory.CreateTempSubdirectory("acphys-verify-dat-").FullName;

    [Fact(DisplayName = "DAT-WORLD-GATE (process): verify over the corpus dat world passes on the reference; outdoor-wins fails it and its replay line reproduces from the files")]
    public void GateFailsUnderAFaultAndTheReplayReproduces()
    {
        string cell = Path.Combine(dir, "cell.dat"), portal = Path.Combine(dir, "portal.dat");
        var files = Directory.GetFiles(Path.Combine(RepoPaths.Corpus, "seeds"), "*.json").Where(f => CorpusJson.ReadFile(f).SceneWalk is not null);
        Assert.Equal(0, Acphys.Run(["scene", "to-dat", .. files, "--cell", cell, "--portal", portal]).Exit);

        var clean = Acphys.Run(["verify", "--only", "LCOORD-BLOCK", "--cell-dat", cell, "--portal-dat", portal, "--dat-blocks", "6"]);
        Assert.True(clean.Exit == 0, clean.ToString());
        Assert.Contains("dat world: 6 of 6 landblocks with buildings or env cells", clean.Out);
        Assert.Contains("0 refused", clean.Out);
        Assert.Contains("0 violated", clean.Out);

        var faulted = Acphys.Run(["verify", "--only", "LCOORD-BLOCK", "--cell-dat", cell, "--portal-dat", portal, "--dat-blocks", "6", "--fault", "outdoor-wins"]);
        Assert.True(faulted.Exit == 1, faulted.ToString());
        Assert.Contains("FAIL  INTERIOR-WINS in landblock 0xA9B4, walk from 0xA9B40100 through portal 0", faulted.Out);
        string replay = faulted.Out.Split('\n').Select(l => l.Trim()).First(l => l.StartsWith("replay     ", StringComparison.Ordinal) && l.Contains("--dat-block 0xA9B4", StringComparison.Ordinal));
        var words = replay["replay     ".Length..].Split(' ');
        Assert.Equal("verify", words[1]);

        var again = Acphys.Run(words[1..]);
        Assert.True(again.Exit == 1, again.ToString());
        Assert.Contains("FAIL  INTERIOR-WINS in landblock 0xA9B4, walk from 0xA9B40100 through portal 0", again.Out);
        Assert.DoesNotContain("LCOORD-BLOCK", again.Out); // the replay walks that block alone
    }

    [Fact(DisplayName = "verify --cell-dat without --portal-dat is a usage error (exit 2); a damaged dat is exit 5")]
    public void BadDatOptions()
    {
        var alone = Acphys.Run(["verify", "--cell-dat", "x.dat"]);
        Assert.Equal(2, alone.Exit);
        Assert.Contains("--cell-dat and --portal-dat go together", alone.Err);

        string junk = Path.Combine(dir, "junk.dat");
        File.WriteAllBytes(junk, new byte[100]);
        var damaged = Acphys.Run(["verify", "--cell-dat", junk, "--portal-dat", junk, "--dat-block", "0x0101"]);
        Assert.Equal(5, damaged.Exit);
        Assert.Contains("truncated", damaged.Err);
    }

    public void Dispose() => Directory.Delete(dir, recursive: true);
}
