using System.Globalization;
using System.Text;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// CAPTURE-RENDER: <c>acphys render</c> on a capture and on its minimised walk, as a process. The captures are written
/// here from the documented native format (docs/corpus-format.md, "Captures"), not by the reader's code: a walk south
/// at x = 150 from 0xA9B40031 across the line into 0xA9B30038, clean (the true cell) or frozen as clamp-106 freezes it.
/// </summary>
public sealed class CaptureRenderTests
{
    [Fact(DisplayName = "CAPTURE-RENDER: a frozen capture's picture marks the divergent span and labels its first frame; a clean one has no span mark")]
    public void FrozenMarkedCleanNot()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-render-").FullName;
        string frozen = Write(Path.Combine(dir, "frozen.tsv"), 40, 0.1, frozenCell: true);
        string clean = Write(Path.Combine(dir, "clean.tsv"), 40, 0.1, frozenCell: false);

        var bad = Acphys.Run(["render", frozen, "-o", Path.Combine(dir, "frozen.svg")]);
        Assert.True(bad.Exit == 0, bad.ToString());
        string svg = File.ReadAllText(Path.Combine(dir, "frozen.svg"));
        Assert.Contains("class=\"span\"", svg, StringComparison.Ordinal);
        Assert.Contains("class=\"span-start\"", svg, StringComparison.Ordinal);
        Assert.Contains("first divergence: frame 20", svg, StringComparison.Ordinal);
        Assert.Contains("class=\"span-label\"", svg, StringComparison.Ordinal);
        Assert.Contains(">first divergence: frame 20; F1 [cell-held-across-block-line]</text>", svg, StringComparison.Ordinal); // the label on the map, not only the header

        var ok = Acphys.Run(["render", clean, "-o", Path.Combine(dir, "clean.svg")]);
        Assert.True(ok.Exit == 0, ok.ToString());
        string cleanSvg = File.ReadAllText(Path.Combine(dir, "clean.svg"));
        Assert.DoesNotContain("class=\"span", cleanSvg, StringComparison.Ordinal);
        Assert.DoesNotContain("first divergence: frame", cleanSvg, StringComparison.Ordinal);
        Assert.Contains("class=\"agree\"", cleanSvg, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "CAPTURE-RENDER: a 200,000-frame capture renders under 400 KB, the first divergence still labelled")]
    public void LongCaptureStaysSmall()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-render-").FullName;
        string frozen = Write(Path.Combine(dir, "long.tsv"), 200_000, 0.001, frozenCell: true);
        string output = Path.Combine(dir, "long.svg");
        var run = Acphys.Run(["render", frozen, "-o", output]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("200,000 frames", run.Out, StringComparison.Ordinal);
        Assert.InRange(new FileInfo(output).Length, 1, 400_000);
        // y = 1.95 − 0.001·i is 0 at i = 1950; frames within the printed precision of the line are not judged.
        var first = System.Text.RegularExpressions.Regex.Match(File.ReadAllText(output), "first divergence: frame ([0-9]+)");
        Assert.True(first.Success, run.ToString());
        Assert.InRange(int.Parse(first.Groups[1].Value, CultureInfo.InvariantCulture), 1951, 1953);
    }

    [Fact(DisplayName = "CAPTURE-RENDER: the minimised walk's picture shows the port's recorded cell against the reference's")]
    public void MinimisedWalkShowsRecorded()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-render-").FullName;
        string frozen = Write(Path.Combine(dir, "frozen.tsv"), 40, 0.1, frozenCell: true);
        string minimised = Path.Combine(dir, "min");
        var check = Acphys.Run(["capture", "check", frozen, "--quiet", "--minimise", minimised]);
        Assert.True(check.Exit == 1, check.ToString());
        string walk = Directory.GetFiles(minimised, "*.json").Single();

        string output = Path.Combine(dir, "walk.svg");
        var run = Acphys.Run(["render", walk, "-o", output]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("NO-BOUNDARY-FREEZE", run.Out, StringComparison.Ordinal); // the recorded answers are judged, as replay judges them
        string svg = File.ReadAllText(output);
        Assert.Contains("class=\"reference-cell\"", svg, StringComparison.Ordinal);
        Assert.Contains("0xA9B30038", svg, StringComparison.Ordinal); // the reference's cell in the legend
        Assert.Contains("recorded answers", svg, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "CAPTURE-RENDER: a malformed capture is exit 2 naming file and line, and no picture is written")]
    public void MalformedIsExitTwo()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-capture-render-").FullName;
        string nan = Path.Combine(dir, "nan.tsv");
        File.WriteAllText(nan, "0\t0xA9B40031\t150.000\t1.000\t0.000\n1\t0xA9B40031\tNaN\t0.9\t0.000\n");
        string output = Path.Combine(dir, "nan.svg");
        var run = Acphys.Run(["render", nan, "-o", output]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains($"{nan}:2: x: expected a finite decimal number", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", run.Err, StringComparison.Ordinal);
        Assert.False(File.Exists(output));
    }

    // frame cell x y z, block frame: y from 1.95 down by `step`; frozen keeps 0xA9B40031 (y negative in its block), clean
    // names the true cell (cell index 1 + 8·gx + gy in its block).
    private static string Write(string path, int frames, double step, bool frozenCell)
    {
        var sb = new StringBuilder("# frame: block\n");
        for (int i = 0; i < frames; i++)
        {
            double y = Math.Round(1.95 - (step * i), 3);
            double wy = (0xB4 * 192.0) + y;
            int by = (int)Math.Floor(wy / 192), gy = (int)Math.Floor((wy - (by * 192.0)) / 24);
            string cell = frozenCell || by == 0xB4 ? $"0xA9B400{1 + (6 * 8):X2}" : $"0xA9{by:X2}00{1 + (6 * 8) + gy:X2}";
            double ly = frozenCell ? y : wy - (by * 192.0);
            sb.Append(CultureInfo.InvariantCulture, $"{i}\t{cell}\t150.000\t{ly:0.000}\t0.000\n");
        }

        File.WriteAllText(path, sb.ToString());
        return path;
    }
}
