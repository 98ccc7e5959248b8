using System.Text.Json.Nodes;
using System.Xml.Linq;
using AcPhys.E2E.Support;

namespace AcPhys.E2E.Hostile;

/// <summary>
/// Issue 28, sizes and numbers: inputs whose work grows with a size are bounded alike in files and on the wire, and
/// every option number is checked before anything starts.
/// </summary>
public sealed class HostileInputTests
{
    private static readonly string PartsFile = Path.Combine(RepoPaths.Corpus, "regressions", "PARTS-COVERAGE-3dbac145.json");

    /// <summary>PARTS-BOUNDED: a corpus file with a ±1e30 m box, or an always2d part with r = 1e30, is refused at once (exit 2) naming the field.</summary>
    [Theory]
    [InlineData("box", "$.parts[0].min: every component must be within ±200 m")]
    [InlineData("radius", "$.parts[0].radius: must be at most 200 m")]
    public void Replay_HugeParts_IsRefusedAtOnce(string what, string message)
    {
        var entry = JsonNode.Parse(File.ReadAllText(PartsFile))!;
        var part = entry["parts"]![0]!;
        if (what == "box")
        {
            part["min"] = new JsonObject { ["x"] = -1e30, ["y"] = -1e30, ["z"] = 0 };
            part["max"] = new JsonObject { ["x"] = 1e30, ["y"] = 1e30, ["z"] = 0 };
        }
        else
        {
            part["radius"] = 1e30;
            part["always2d"] = true;
        }

        var run = Acphys.Run(["replay", HostileFiles.Write("huge.json", entry.ToJsonString())]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains(message, run.Err, StringComparison.Ordinal);
        Assert.True(run.Elapsed < TimeSpan.FromSeconds(60), run.ToString());
    }

    /// <summary>PARTS-BOUNDED: serve answers a ±1e30 m box, 1,000 parts (own input 8) or parts four blocks apart (own input 9) with an error and keeps answering.</summary>
    [Fact]
    public async Task Serve_HugeParts_IsAnErrorAndServeGoesOn()
    {
        const string Part = "{{\"cell\":\"{0}\",\"origin\":{{\"x\":1,\"y\":1,\"z\":0.5}},\"rotation\":{{\"x\":0,\"y\":0,\"z\":0,\"w\":1}},\"min\":{{\"x\":{1},\"y\":{1},\"z\":0}},\"max\":{{\"x\":{2},\"y\":{2},\"z\":0}},\"r\":{3},\"always2d\":{4}}}";
        string P(string cell, string min, string max, string r, string always) => string.Format(System.Globalization.CultureInfo.InvariantCulture, Part, cell, min, max, r, always);
        var lines = new[]
        {
            "{\"op\":\"hello\",\"protocol\":1}",
            "{\"op\":\"outside_cells_parts\",\"parts\":[" + P("0x00040001", "-1e30", "1e30", "1", "false") + "]}",
            "{\"op\":\"outside_cells_parts\",\"parts\":[" + P("0x00040001", "-1", "1", "1e30", "true") + "]}",
            "{\"op\":\"outside_cells_parts\",\"parts\":[" + string.Join(',', Enumerable.Repeat(P("0x00040001", "-1", "1", "1", "false"), 1_000)) + "]}",
            "{\"op\":\"outside_cells_parts\",\"parts\":[" + P("0x00040001", "-1", "1", "1", "false") + "," + P("0x08080001", "-1", "1", "1", "false") + "]}",
            "{\"op\":\"lcoord_to_gid\",\"x\":1,\"y\":1}",
        };
        var info = Acphys.Info(["serve"], stdin: true);
        using var process = System.Diagnostics.Process.Start(info)!;
        var output = process.StandardOutput.ReadToEndAsync();
        foreach (string line in lines)
        {
            process.StandardInput.WriteLine(line);
        }

        process.StandardInput.Close();
        Assert.True(process.WaitForExit(TimeSpan.FromSeconds(60)), "serve did not finish");
        var answers = (await output).Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(6, answers.Length);
        Assert.Contains("parts[0].min", answers[1], StringComparison.Ordinal);
        Assert.Contains("parts[0].r", answers[2], StringComparison.Ordinal);
        Assert.Contains("expected an array of 1 to 256 parts", answers[3], StringComparison.Ordinal);
        Assert.Contains("first part's block or a neighbour", answers[4], StringComparison.Ordinal);
        Assert.Equal("{\"cell\":\"0x0000000A\"}", answers[5]);
    }

    /// <summary>CATCHES-BOUNDED: a corpus file listing 2,000,000 catches is refused at once (exit 2).</summary>
    [Fact]
    public void Replay_TwoMillionCatches_IsRefusedAtOnce()
    {
        var entry = JsonNode.Parse(File.ReadAllText(PartsFile))!;
        entry["catches"] = new JsonArray();
        string text = entry.ToJsonString().Replace("\"catches\":[]", "\"catches\":[" + string.Join(',', Enumerable.Repeat("\"c\"", 2_000_000)) + "]", StringComparison.Ordinal);
        var run = Acphys.Run(["replay", HostileFiles.Write("catches.json", text)]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("$.catches: expected at most 256 fault ids, got 2,000,000", run.Err, StringComparison.Ordinal);
        Assert.True(run.Elapsed < TimeSpan.FromSeconds(60), run.ToString());
    }

    /// <summary>SCENE-WALK-START: a scene walk that starts in an env cell the scene does not hold is refused (exit 2), not passed as VACUOUS.</summary>
    [Fact]
    public void SceneWalk_StartingInAnUndeclaredEnvCell_IsRefused()
    {
        var entry = JsonNode.Parse(File.ReadAllText(Path.Combine(RepoPaths.Corpus, "seeds", "cottage-a9b3-a9b4-through.json")))!;
        entry["walk"]!["start"]!["cell"] = "0xA9B40155";
        var run = Acphys.Run(["replay", HostileFiles.Write("start.json", entry.ToJsonString())]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("$.walk.start.cell: the walk starts in env cell 0xA9B40155, which the scene does not hold", run.Err, StringComparison.Ordinal);
    }

    /// <summary>BUILDING-PORTAL: a building portal naming portal 99 of a two-portal cell is refused (exit 2).</summary>
    [Fact]
    public void BuildingPortal_OutOfRange_IsRefused()
    {
        var entry = JsonNode.Parse(File.ReadAllText(Path.Combine(RepoPaths.Corpus, "seeds", "cottage-a9b3-a9b4-through.json")))!;
        entry["scene"]!["buildings"]![0]!["portals"]![0]!["portal"] = 99;
        var run = Acphys.Run(["replay", HostileFiles.Write("portal.json", entry.ToJsonString())]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("$.scene.buildings[0].portals[0].portal: cell 0xA9B40100 has 2 portals (0..1, or 65535 for none), not portal 99", run.Err, StringComparison.Ordinal);
    }

    /// <summary>FUZZ-OPTIONS: NaN and huge minutes, 1000 jobs, --no-build without a build, --triage-only without a campaign, and --triage-only --fresh (own input 10) are exit 2 before anything is installed or built.</summary>
    [Fact]
    public void FuzzOptions_AreCheckedBeforeAnyWork()
    {
        string empty = HostileFiles.Temp();
        var cases = new (string[] Args, string Message)[]
        {
            (["fuzz", "--minutes", "NaN"], "got --minutes NaN"),
            (["fuzz", "--minutes", "1e300"], "--minutes (a number of minutes up to 10080)"),
            (["fuzz", "--jobs", "1000"], "--jobs 1000: at most"),
            (["fuzz", "--no-build", "--build-dir", empty], "--no-build: no instrumented build in"),
            (["fuzz", "--triage-only", "--campaign", Path.Combine(empty, "nonexistent")], "--triage-only: no campaign to triage in"),
            (["fuzz", "--triage-only", "--fresh", "--campaign", empty], "--triage-only and --fresh exclude each other"),
        };
        foreach (var (args, message) in cases)
        {
            var run = Acphys.Run(args);
            Assert.True(run.Exit == 2, string.Join(' ', args) + "\n" + run);
            Assert.Contains(message, run.Err, StringComparison.Ordinal);
            Assert.DoesNotContain("build: publishing", run.Out + run.Err, StringComparison.Ordinal);
            Assert.DoesNotContain("apt-get", run.Out + run.Err, StringComparison.Ordinal);
        }
    }

    /// <summary>TIMEOUT-BOUNDED: --timeout below 0.1 s is a usage error (exit 2), for --impl-cmd and --impl alike.</summary>
    [Theory]
    [InlineData("1e-9")]
    [InlineData("0.05")]
    public void Timeout_TooShort_IsAUsageError(string seconds)
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand, "--timeout", seconds, "--only", "ADJUST-RANGE"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains($"malformed --timeout '{seconds}': expected seconds, a number from 0.1 to 3600", run.Err, StringComparison.Ordinal);
    }

    /// <summary>HELP-POINTER: a parse error in a nested verb points to that verb's help.</summary>
    [Fact]
    public void Tradeoffs_ParseError_PointsToItsOwnHelp()
    {
        var run = Acphys.Run(["tradeoffs", "accuracy", "--seed", "x"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("Run 'acphys tradeoffs accuracy --help' for usage.", run.Err, StringComparison.Ordinal);
    }

    /// <summary>RENDER-ALL-ROWS: every step row and key line of a scene-walk picture lies inside the picture and is not cut.</summary>
    [Fact]
    public void SceneRender_HoldsAllItsRows()
    {
        string svg = Path.Combine(HostileFiles.Temp(), "cottage.svg");
        var run = Acphys.Run(["render", Path.Combine(RepoPaths.Corpus, "seeds", "cottage-a9b3-a9b4-through.json"), "-o", svg]);
        Assert.True(run.Exit == 0, run.ToString());
        var root = XDocument.Load(svg).Root!;
        double[] box = ((string)root.Attribute("viewBox")!).Split(' ').Select(v => double.Parse(v, System.Globalization.CultureInfo.InvariantCulture)).ToArray();
        double bottom = box[1] + box[3];
        var texts = root.Descendants().Where(e => e.Name.LocalName == "text").ToList();
        var steps = texts.Where(t => (string?)t.Attribute("class") == "legend-step").ToList();
        Assert.Equal(new[] { "0", "8", "25", "41", "48" }, steps.Select(t => t.Value.Trim().Split(' ')[0]));
        Assert.All(texts, t => Assert.True(double.Parse((string)t.Attribute("y")!, System.Globalization.CultureInfo.InvariantCulture) < bottom, $"'{t.Value}' lies below the picture"));
        Assert.All(steps, t => Assert.DoesNotContain("…", t.Value, StringComparison.Ordinal));
        Assert.Contains(texts, t => t.Value.StartsWith("portals: orange", StringComparison.Ordinal) && !t.Value.EndsWith('…'));
    }

    /// <summary>DOCS-CURRENT: docs/cli.md shows the catalogue's and the fault list's counts of today, and how to build the .NET adapter example.</summary>
    [Fact]
    public void CliDoc_ShowsTodaysCountsAndTheAdapterBuild()
    {
        string doc = File.ReadAllText(Path.Combine(RepoPaths.Root, "docs", "cli.md"));
        var invariants = Acphys.Run(["invariants"]);
        var faults = Acphys.Run(["faults"]);
        int invariantCount = Count(invariants.Out, "invariants"), faultCount = Count(faults.Out, "planted faults");
        Assert.Contains($"acphys invariants                    # {invariantCount} invariants", doc, StringComparison.Ordinal);
        Assert.Contains($"acphys faults                        # {faultCount} planted faults", doc, StringComparison.Ordinal);
        Assert.Contains("dotnet build examples/dotnet-adapter/ExampleAdapter.csproj -c Release", doc, StringComparison.Ordinal);
    }

    // The count a listing states in its last line ("42 invariants", "51 faults").
    private static int Count(string listing, string noun)
    {
        var match = System.Text.RegularExpressions.Regex.Match(listing, $@"(\d+) {noun}");
        Assert.True(match.Success, $"no '{noun}' count in:\n{listing}");
        return int.Parse(match.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture);
    }
}
