using AcPhys.E2E.Support;
using AcPhys.Formats.Corpus;
using AcPhys.Fuzz.Targets;
using AcPhys.Spec.Corpus;

namespace AcPhys.E2E;

/// <summary>
/// A failure found anywhere replays where it is replayed (issue 25): the case file verify, diff or a fuzz campaign
/// writes, replayed with the line printed beside it, exits 1 naming the invariant, and render of it names it too;
/// a walk the reference cannot judge is never reported as the reference violating an invariant.
/// </summary>
public sealed class ReplayReproducesTests
{
    [Theory(DisplayName = "REPLAY-REPRODUCES: the case file verify writes for a planted fault replays with its printed line to exit 1 naming the invariant; render names it; the file says verify found it")]
    [InlineData("blockid-zero-ok", "LANDDEFS-CONFORMANCE")]
    [InlineData("first-hit-outdoor-pick", "FIND-CELL-QUERY-CONFORMANCE")]
    [InlineData("touch-inclusive", "OUTSIDE-CELLS-CONFORMANCE")]
    [InlineData("touch-inclusive", "FIND-CELL-QUERY-CONFORMANCE")]
    [InlineData("close-is-outside", "FIND-CELL-CONFORMANCE")]
    [InlineData("clamp-106", "NO-BOUNDARY-FREEZE")]
    [InlineData("outdoor-wins", "INTERIOR-WINS")]
    public void VerifysCaseFileReplaysToItsInvariant(string fault, string invariant)
    {
        string dir = Directory.CreateTempSubdirectory("acphys-reproduce-").FullName;
        var env = new Dictionary<string, string> { ["ACPHYS_FAILURES"] = dir };
        var verify = Acphys.Run(["verify", "--fault", fault, "--only", invariant, "--max-classes", "1"], env);
        Assert.True(verify.Exit == 1, verify.ToString());
        string file = Assert.Single(Directory.GetFiles(dir, invariant + "-*.json"));
        Assert.Equal(FinderNames.Verify, CorpusJson.ReadFile(file).FoundBy);

        // The printed line, as a user copies it: "acphys replay FILE --fault F".
        string line = verify.Out.Split('\n').Select(l => l.Trim()).Single(l => l.StartsWith("replay     acphys replay ", StringComparison.Ordinal))["replay     acphys ".Length..];
        var replay = Acphys.Run(line.Split(' '), env);
        Assert.True(replay.Exit == 1, $"{line}\n{replay}");
        Assert.Contains($"VIOLATED {invariant}", replay.Out, StringComparison.Ordinal);
        Assert.Contains(invariant, replay.Out.Split('\n').Single(l => l.StartsWith("replay: ", StringComparison.Ordinal)), StringComparison.Ordinal);

        string svg = Path.Combine(dir, "case.svg");
        var render = Acphys.Run(["render", file, "--fault", fault, "-o", svg]);
        Assert.True(render.Exit == 0, render.ToString());
        Assert.Contains(invariant, render.Out, StringComparison.Ordinal);
        Assert.Contains(invariant, File.ReadAllText(svg), StringComparison.Ordinal);
    }

    [Fact(DisplayName = "REPLAY-REPRODUCES: a fuzz finding's regression file replays under the campaign's fault to exit 1 naming the finding's invariant, and holds on the reference")]
    public void FuzzFindingReplaysToItsInvariant()
    {
        var target = (WalkTarget)FuzzTargets.Find("walk")!;
        byte[] crash = [0x31, 0x00, 0x24, 0x3A, 0x00, 0x40, 0x00, 0x40, 0x00, 0x10, 0x05, 0x7F, 0x00, 0x05, 0x10, 0x20];
        var finding = target.Classify(crash, "sticky-pick")!;
        var entry = target.Minimise(finding, "sticky-pick", "e2e")!;
        string file = Path.Combine(Directory.CreateTempSubdirectory("acphys-reproduce-").FullName, FailureFile.NameFor(entry));
        File.WriteAllText(file, CorpusJson.Write(entry));
        Assert.Equal(FinderNames.Fuzz, entry.FoundBy);

        var onFault = Acphys.Run(["replay", file, "--fault", "sticky-pick"]);
        Assert.True(onFault.Exit == 1, onFault.ToString());
        Assert.Contains($"VIOLATED {finding.Key}", onFault.Out, StringComparison.Ordinal);
        var onReference = Acphys.Run(["replay", file]);
        Assert.True(onReference.Exit == 0, onReference.ToString());
    }

    [Fact(DisplayName = "REPLAY-REPRODUCES: every case file diff writes replays against the diverging port to exit 1 naming a conformance invariant, and holds on the reference")]
    public void DiffCaseFilesReplayAgainstThePort()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-reproduce-").FullName;
        string port = Acphys.ServeCommand + " --fault touch-inclusive";
        var diff = Acphys.Run(["diff", "--impl-cmd", port, "--only", "DIFF-OUTSIDE-CELLS", "--cases", "300", "--timeout", "60", "-o", dir]);
        Assert.True(diff.Exit == 1, diff.ToString());
        var files = Directory.GetFiles(dir, "DIFF-OUTSIDE-CELLS-*.json");
        Assert.NotEmpty(files);
        foreach (string file in files)
        {
            Assert.Equal(FinderNames.Diff, CorpusJson.ReadFile(file).FoundBy);
            var onPort = Acphys.Run(["replay", file, "--impl-cmd", port, "--timeout", "60"]);
            Assert.True(onPort.Exit == 1, onPort.ToString());
            Assert.Contains("VIOLATED OUTSIDE-CELLS-CONFORMANCE", onPort.Out, StringComparison.Ordinal);
            var onReference = Acphys.Run(["replay", file]);
            Assert.True(onReference.Exit == 0, onReference.ToString());
        }
    }

    [Theory(DisplayName = "REPLAY-UNJUDGEABLE: a walk starting at id 0, 0xFFFFFFFF or a malformed id replays on the reference as vacuous for the walk invariants, never as the reference violating one")]
    [InlineData("0x00000000")]
    [InlineData("0xFFFFFFFF")]
    [InlineData("0xA9B40077")]
    public void WalkFromANonCellIsNotAReferenceViolation(string start)
    {
        string file = Path.Combine(Directory.CreateTempSubdirectory("acphys-reproduce-").FullName, "walk.json");
        File.WriteAllText(file, $$$"""
            {"format":"acphys-case","version":1,"kind":"walk","title":"from {{{start}}}","foundBy":"hand","catches":[],
             "walk":{"start":{"cell":"{{{start}}}","x":100,"y":100,"z":0},"body":[{"x":0,"y":0,"z":0.5,"r":0.5}],"steps":[[30,0],[30,0],[0,30]]}}
            """);
        var replay = Acphys.Run(["replay", file]);
        Assert.True(replay.Exit == 0, replay.ToString());
        Assert.Contains("VACUOUS NO-BOUNDARY-FREEZE: the walk starts at " + start, replay.Out, StringComparison.Ordinal);
        Assert.DoesNotContain("VIOLATED", replay.Out, StringComparison.Ordinal);
    }
}
