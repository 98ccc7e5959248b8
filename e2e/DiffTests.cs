using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>acphys diff: the same answers as the reference give no divergence; every divergence class of a seeded bug is counted, shrunk and written as a replayable walk beside a side-by-side table.</summary>
public sealed class DiffTests
{
    [RequiresPythonFact]
    public void PythonExampleAnswersLikeTheReference()
    {
        var run = Acphys.Run(["diff", "--impl-cmd", Acphys.PythonExample, "--cases", "300", "--timeout", "60", "-o", Directory.CreateTempSubdirectory("acphys-diff-").FullName]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("diff: 6 checks, 6 same, 0 differ, 0 not compared", run.Out, StringComparison.Ordinal); // outside_cells_parts (DIFF-PARTS) and scene walks compared too
    }

    [RequiresPythonFact]
    public void SeededBugFirstDivergenceIsAShrunkWalkFileWithBothAnswers()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-diff-").FullName;
        var run = Acphys.Run(["diff", "--impl-cmd", Acphys.PythonExample + " --bug clamp-106", "--only", "DIFF-WALK", "--cases", "300", "--timeout", "60", "-o", dir]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Matches(@"DIFFERS DIFF-WALK: \d+ of 300 inputs differ \(.*\) in 1 class; python-example\+clamp-106 vs reference", run.Out);
        Assert.Contains("D1  ", run.Out, StringComparison.Ordinal);
        Assert.Contains("find_cell along the walk: missing cells (other block)", run.Out, StringComparison.Ordinal);

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
    public void EveryDivergenceClassIsListedWithItsCountAndFiles()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-diff-").FullName;
        var run = Acphys.Run(["diff", "--impl-cmd", Acphys.ServeCommand + " --fault clamp-106,touch-inclusive", "--only", "DIFF-OUTSIDE-CELLS", "--cases", "500", "--timeout", "60", "-o", dir]);
        Assert.True(run.Exit == 1, run.ToString());

        // The header's count of differing inputs is the sum of the classes' counts.
        var header = System.Text.RegularExpressions.Regex.Match(run.Out, @"DIFFERS DIFF-OUTSIDE-CELLS: (\d+) of 500 inputs differ .* in (\d+) classes");
        Assert.True(header.Success, run.ToString());
        var counts = System.Text.RegularExpressions.Regex.Matches(run.Out, @"^  D\d+  (\d+) inputs?  (.*)$", System.Text.RegularExpressions.RegexOptions.Multiline);
        Assert.Equal(int.Parse(header.Groups[2].Value, System.Globalization.CultureInfo.InvariantCulture), counts.Count);
        Assert.Equal(int.Parse(header.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture), counts.Sum(m => int.Parse(m.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture)));
        Assert.Contains(counts, m => m.Groups[2].Value == "outside_cells: missing cells (other block)");
        Assert.Contains(counts, m => m.Groups[2].Value == "outside_cells: extra cells");

        // One replayable case file and one side-by-side file per class; summary.md lists every class.
        Assert.Equal(counts.Count, Directory.GetFiles(dir, "DIFF-OUTSIDE-CELLS-*.diff.md").Length);
        Assert.InRange(Directory.GetFiles(dir, "DIFF-OUTSIDE-CELLS-*.json").Length, 1, counts.Count); // one file per class (a query is stored as asked, spheres or none)
        string summary = File.ReadAllText(Path.Combine(dir, "summary.md"));
        Assert.Contains("| `DIFF-OUTSIDE-CELLS` | D2 |", summary, StringComparison.Ordinal);
        Assert.Contains("diff: 1 checks, 0 same, 1 differ, 0 not compared; " + counts.Count + " divergence classes over " + header.Groups[1].Value + " inputs", run.Out, StringComparison.Ordinal);
    }

    [Fact]
    public void DiffWithoutAnImplementationIsExit2()
    {
        var run = Acphys.Run(["diff"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("diff needs an implementation to compare", run.Err, StringComparison.Ordinal);
    }
}
