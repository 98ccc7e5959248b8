using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>acphys diff: the same answers as the reference give no divergence; a seeded bug's first divergence is shrunk and written as a replayable walk beside a side-by-side table.</summary>
public sealed class DiffTests
{
    [RequiresPythonFact]
    public void PythonExampleAnswersLikeTheReference()
    {
        var run = Acphys.Run(["diff", "--impl-cmd", Acphys.PythonExample, "--cases", "300", "--timeout", "60", "-o", Directory.CreateTempSubdirectory("acphys-diff-").FullName]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("diff: 5 checks, 4 same, 0 differ, 1 not compared", run.Out, StringComparison.Ordinal); // no outside_cells_parts
    }

    [RequiresPythonFact]
    public void SeededBugFirstDivergenceIsAShrunkWalkFileWithBothAnswers()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-diff-").FullName;
        var run = Acphys.Run(["diff", "--impl-cmd", Acphys.PythonExample + " --bug clamp-106", "--only", "DIFF-WALK", "--cases", "300", "--timeout", "60", "-o", dir]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("DIFFERS DIFF-WALK: python-example+clamp-106 vs reference", run.Out, StringComparison.Ordinal);

        string walkFile = Assert.Single(Directory.GetFiles(dir, "DIFF-WALK-*.json"));
        Assert.Contains("\"kind\": \"walk\"", File.ReadAllText(walkFile), StringComparison.Ordinal);
        string side = File.ReadAllText(Assert.Single(Directory.GetFiles(dir, "DIFF-WALK-*.diff.md")));
        Assert.Contains("| query | python-example+clamp-106 | reference | |", side, StringComparison.Ordinal);
        Assert.Contains("**differs**", side, StringComparison.Ordinal);

        // The walk file replays: on the reference it holds, on the buggy implementation an invariant breaks.
        var onReference = Acphys.Run(["replay", walkFile]);
        Assert.True(onReference.Exit == 0, onReference.ToString());
        var onBug = Acphys.Run(["replay", walkFile, "--impl-cmd", Acphys.PythonExample + " --bug clamp-106", "--timeout", "60"]);
        Assert.True(onBug.Exit == 1, onBug.ToString());
    }

    [Fact]
    public void DiffWithoutAnImplementationIsExit2()
    {
        var run = Acphys.Run(["diff"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("diff needs an implementation to compare", run.Err, StringComparison.Ordinal);
    }
}
