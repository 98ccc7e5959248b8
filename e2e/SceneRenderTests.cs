using System.Globalization;
using System.Numerics;
using System.Text.Json.Nodes;
using System.Xml.Linq;
using AcPhys.E2E.Support;
using AcPhys.Formats.Corpus;

namespace AcPhys.E2E;

/// <summary>
/// acphys render and replay of scene walks: a well-formed SVG with one outline per env cell and one mark per portal,
/// outlines at the frame-transformed corners, the failing step of a planted indoor fault marked, malformed files
/// refused with a one-line message and exit 2.
/// </summary>
public sealed class SceneRenderTests
{
    private static readonly XNamespace Svg = "http://www.w3.org/2000/svg";

    /// <summary>Gets the stored scene walks.</summary>
    public static TheoryData<string> SceneWalks => ["cottage-a9b3-a9b4-in-and-out.json", "cottage-a9b3-a9b4-through.json"];

    [Theory]
    [MemberData(nameof(SceneWalks))]
    public void RenderDrawsOneOutlinePerEnvCellAndOneMarkPerPortal(string name)
    {
        string path = Seed(name);
        var scene = CorpusJson.ReadFile(path).SceneWalk!.Scene;
        string dir = Directory.CreateTempSubdirectory("acphys-render-").FullName;
        string svg = Path.Combine(dir, "scene.svg");

        var run = Acphys.Run(["render", path, "-o", svg]);
        Assert.True(run.Exit == 0, run.ToString());
        var doc = XDocument.Load(svg); // well-formed XML, or this throws
        Assert.Equal(Svg + "svg", doc.Root!.Name);

        var outlines = WithClass(doc, "cell-outline").ToList();
        Assert.Equal(scene.Cells.Select(c => "cell-" + c.Id).Order(), outlines.Select(e => (string)e.Attribute("id")!).Order());
        Assert.All(outlines, g => Assert.Equal(scene.Cells.Single(c => "cell-" + c.Id == (string)g.Attribute("id")!).Pieces.Count, g.Elements(Svg + "polygon").Count()));

        var portals = WithClass(doc, "portal").ToList();
        var expected = scene.Cells.SelectMany(c => c.Portals.Select((p, i) => (Id: $"portal-{c.Id}-{i}", Kind: p.IsExit ? "exit" : "inter"))).ToList();
        Assert.Equal(expected.Select(p => p.Id).Order(), portals.Select(e => (string)e.Attribute("id")!).Order());
        Assert.All(expected, p => Assert.Contains(p.Kind, Classes(portals.Single(e => (string)e.Attribute("id")! == p.Id))));
        Assert.Equal(scene.Buildings.Sum(b => b.Portals.Count), WithClass(doc, "bld-portal").Count());
        Assert.Equal(scene.Buildings.Count, WithClass(doc, "building").Count());
        Assert.Empty(WithClass(doc, "fail")); // the reference passes these walks
        Assert.Empty(Directory.GetFiles(dir, ".*.tmp")); // written atomically
    }

    [Fact]
    public void RotatedCottageOutlineCornersAreTheFrameTransformedBoxCorners()
    {
        string path = Seed("cottage-a9b3-a9b4-through.json");
        var scene = CorpusJson.ReadFile(path).SceneWalk!.Scene;
        Assert.All(scene.Cells, c => Assert.True(Math.Abs(c.Rotation.W) < 0.9f, "premise: the cottage is rotated")); // not the identity frame
        string svg = Path.Combine(Directory.CreateTempSubdirectory("acphys-render-").FullName, "through.svg");
        var run = Acphys.Run(["render", path, "-o", svg]);
        Assert.True(run.Exit == 0, run.ToString());

        var doc = XDocument.Load(svg);
        foreach (var cell in scene.Cells)
        {
            var box = cell.Pieces.Single().Box!.Value;
            var expected = new[] { (box.Min.X, box.Min.Y), (box.Max.X, box.Min.Y), (box.Max.X, box.Max.Y), (box.Min.X, box.Max.Y) }
                .Select(c => cell.Origin + Vector3.Transform(new Vector3(c.Item1, c.Item2, box.Min.Z), cell.Rotation))
                .Select(p => ((192.0 * cell.Id.BlockX) + p.X, (192.0 * cell.Id.BlockY) + p.Y))
                .ToList();
            var drawn = Corners(doc, cell.Id.ToString());

            Assert.Equal(4, drawn.Count);
            foreach (var (x, y) in expected)
            {
                double nearest = drawn.Min(d => Math.Max(Math.Abs(d.X - x), Math.Abs(d.Y - y)));
                Assert.True(nearest < 2e-3, $"{cell.Id}: corner ({x}, {y}) is {nearest} m from the drawn outline [{string.Join(", ", drawn)}]");
            }
        }
    }

    [Fact]
    public void PlaneListPieceIsItsPolygonAndUnloadedThingsAreMarked()
    {
        // The through cottage with room 0x0101 cut to a triangular prism (x ≥ 6, y ≥ 0, x + y ≤ 12, 0 ≤ z ≤ 3), block
        // 0xA9B3 declared unloaded and room 0x0100's inner portal leading to an unloaded cell 0x0102.
        var json = JsonNode.Parse(File.ReadAllText(Seed("cottage-a9b3-a9b4-through.json")))!;
        var scene = json["scene"]!;
        scene["blocks"] = new JsonArray([.. scene["blocks"]!.AsArray().Select(b => (string)b!).Where(b => b != "0xA9B3").Select(b => JsonValue.Create(b))]);
        scene["unloadedBlocks"] = new JsonArray("0xA9B3");
        scene["unloadedCells"] = new JsonArray("0xA9B40102");
        scene["cells"]![0]!["portals"]![1]!["other"] = "0x0102";
        scene["cells"]![1]!["pieces"] = JsonNode.Parse("""
            [{"planes": [{"n": [1, 0, 0], "d": -6}, {"n": [0, 1, 0], "d": 0}, {"n": [-1, -1, 0], "d": 12}, {"n": [0, 0, 1], "d": 0}, {"n": [0, 0, -1], "d": 3}]}]
            """);
        string dir = Directory.CreateTempSubdirectory("acphys-render-").FullName;
        string path = Path.Combine(dir, "variant.json"), svg = Path.Combine(dir, "variant.svg");
        File.WriteAllText(path, json.ToJsonString());
        var cell = CorpusJson.ReadFile(path).SceneWalk!.Scene.Cells[1];

        var run = Acphys.Run(["render", path, "-o", svg]);
        Assert.True(run.Exit == 0, run.ToString());
        var doc = XDocument.Load(svg);
        var expected = new[] { (6f, 0f), (12f, 0f), (6f, 6f) }
            .Select(c => cell.Origin + Vector3.Transform(new Vector3(c.Item1, c.Item2, 0), cell.Rotation))
            .Select(p => ((192.0 * cell.Id.BlockX) + p.X, (192.0 * cell.Id.BlockY) + p.Y))
            .ToList();
        var drawn = Corners(doc, cell.Id.ToString());
        Assert.Equal(3, drawn.Count);
        foreach (var (x, y) in expected)
        {
            Assert.True(drawn.Min(d => Math.Max(Math.Abs(d.X - x), Math.Abs(d.Y - y))) < 2e-3, $"corner ({x}, {y}) not among [{string.Join(", ", drawn)}]");
        }

        Assert.Contains("hint", Classes(WithClass(doc, "portal").Single(e => (string)e.Attribute("id")! == "portal-0xA9B40100-1")));
        Assert.Contains(WithClass(doc, "unloaded-block"), e => (string)e.Attribute("data-block")! == "0xA9B3");
        Assert.DoesNotContain(WithClass(doc, "unloaded-block"), e => (string)e.Attribute("data-block")! == "0xA9B4");
    }

    [Fact]
    public void UpperStoreyIsDashedAndLabelledWithItsZRange()
    {
        // Room 0x0101 moved on top of room 0x0100 (same footprint, 3 m up).
        var json = JsonNode.Parse(File.ReadAllText(Seed("cottage-a9b3-a9b4-through.json")))!;
        var upper = json["scene"]!["cells"]![1]!;
        upper["frame"]!["origin"] = new JsonArray(150, 2, 3);
        upper["pieces"] = JsonNode.Parse("""[{"box": {"min": [0, 0, 0], "max": [6, 6, 3]}}]""");
        string dir = Directory.CreateTempSubdirectory("acphys-render-").FullName;
        string path = Path.Combine(dir, "storeys.json"), svg = Path.Combine(dir, "storeys.svg");
        File.WriteAllText(path, json.ToJsonString());

        var run = Acphys.Run(["render", path, "-o", svg]);
        Assert.True(run.Exit == 0, run.ToString());
        var outlines = WithClass(XDocument.Load(svg), "cell-outline").ToDictionary(g => (string)g.Attribute("id")!);
        Assert.DoesNotContain("storey", Classes(outlines["cell-0xA9B40100"]));
        Assert.Contains("storey", Classes(outlines["cell-0xA9B40101"]));
        Assert.Equal("3", (string)outlines["cell-0xA9B40101"].Attribute("data-z-min")!);
        Assert.Equal("6", (string)outlines["cell-0xA9B40101"].Attribute("data-z-max")!);
        Assert.Equal("6 4", (string)outlines["cell-0xA9B40101"].Element(Svg + "polygon")!.Attribute("stroke-dasharray")!);
        Assert.Contains("z 3–6", outlines["cell-0xA9B40101"].Value, StringComparison.Ordinal);
    }

    [Fact]
    public void RenderWithAnIndoorFaultMarksTheStepReplayNamesAsFirstViolation()
    {
        string path = Seed("cottage-a9b3-a9b4-through.json");
        var replay = Acphys.Run(["replay", path, "--fault", "outdoor-wins"]);
        Assert.True(replay.Exit == 1, replay.ToString());
        var summary = replay.Out.Split('\n').Single(l => l.StartsWith("replay: ", StringComparison.Ordinal));
        int first = int.Parse(summary.Split("first at step ")[1].Split(' ')[0], CultureInfo.InvariantCulture);
        Assert.Contains("VIOLATED INTERIOR-WINS: step ", replay.Out, StringComparison.Ordinal);

        // The first violation may be any judge's (FIND-CELL-CONFORMANCE judges replays too since issue 25): the one at that step.
        var atFirst = System.Text.RegularExpressions.Regex.Match(replay.Out, $@"VIOLATED (\S+): step {first.ToString(CultureInfo.InvariantCulture)}\b");
        Assert.True(atFirst.Success, replay.ToString());

        string svg = Path.Combine(Directory.CreateTempSubdirectory("acphys-render-").FullName, "fault.svg");
        var run = Acphys.Run(["render", path, "--fault", "outdoor-wins", "-o", svg]);
        Assert.True(run.Exit == 0, run.ToString()); // render draws; replay and verify judge
        Assert.Contains($"first violation at step {first}", run.Out, StringComparison.Ordinal);
        var doc = XDocument.Load(svg);
        var failing = Assert.Single(WithClass(doc, "fail"));
        Assert.Equal(first.ToString(CultureInfo.InvariantCulture), (string)failing.Attribute("data-step")!);
        Assert.Contains("step", Classes(failing));
        Assert.Contains(atFirst.Groups[1].Value, failing.Value, StringComparison.Ordinal); // its tooltip names the invariant
    }

    [Fact]
    public void ReplayOfASceneWalkShowsEachStepsCellContainingCellAndCandidates()
    {
        var run = Acphys.Run(["replay", Seed("cottage-a9b3-a9b4-through.json")]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("step  cell        position (block frame)", run.Out, StringComparison.Ordinal);
        Assert.Contains("containing  current     candidates / violations", run.Out, StringComparison.Ordinal);
        // The step through the north door: queried from the land cell, contained by room 0x0100, both among the candidates.
        Assert.Matches(@"\n +\d+  0xA9B40031  \(147, [0-9.]+, 0\) +0xA9B40100  0xA9B40100  \[0xA9B40031, 0xA9B40100\]\n", run.Out);
        Assert.DoesNotContain("VIOLATED", run.Out, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("render")]
    [InlineData("replay")]
    public void MalformedSceneWalkIsOneLineAndExit2(string verb)
    {
        string dir = Directory.CreateTempSubdirectory("acphys-render-").FullName;
        var text = File.ReadAllText(Seed("cottage-a9b3-a9b4-through.json"));
        var json = JsonNode.Parse(text)!;
        json["scene"]!["cells"]![0]!["frame"]!["rotation"] = new JsonArray(1, 1, 0, 0);
        var cases = new Dictionary<string, (string Text, string Message)>
        {
            ["quaternion.json"] = (json.ToJsonString(), "$.scene.cells[0].frame.rotation: quaternion"),
            ["truncated.json"] = (text[..(text.Length / 2)], "not valid JSON"),
            ["no-scene.json"] = (RemoveScene(text), "$.scene: missing"),
        };

        foreach (var (name, (content, message)) in cases)
        {
            string path = Path.Combine(dir, name), svg = Path.Combine(dir, name + ".svg");
            File.WriteAllText(path, content);
            var run = Acphys.Run(verb == "render" ? ["render", path, "-o", svg] : ["replay", path]);
            Assert.True(run.Exit == 2, run.ToString()); // 2: bad input, distinct from 1: an invariant violated
            string err = Assert.Single(run.Err.Split('\n', StringSplitOptions.RemoveEmptyEntries));
            Assert.StartsWith($"acphys {verb}: {path}: ", err, StringComparison.Ordinal);
            Assert.Contains(message, err, StringComparison.Ordinal);
            Assert.DoesNotContain("Exception", run.Err, StringComparison.Ordinal);
            Assert.False(File.Exists(svg));
        }
    }

    // The first piece polygon of a cell's outline, mapped back to world metres with the root's data-world-* and data-px-per-m.
    private static List<(double X, double Y)> Corners(XDocument doc, string cell)
    {
        double left = Attr(doc.Root!, "data-world-left"), top = Attr(doc.Root!, "data-world-top"), scale = Attr(doc.Root!, "data-px-per-m");
        var polygon = WithClass(doc, "cell-outline").Single(g => (string)g.Attribute("id")! == "cell-" + cell).Element(Svg + "polygon")!;
        return [.. ((string)polygon.Attribute("points")!).Split(' ')
            .Select(pair => pair.Split(','))
            .Select(xy => (left + (double.Parse(xy[0], CultureInfo.InvariantCulture) / scale), top - (double.Parse(xy[1], CultureInfo.InvariantCulture) / scale)))];
    }

    private static string Seed(string name) => Path.Combine(RepoPaths.Corpus, "seeds", name);

    private static string RemoveScene(string text)
    {
        var node = JsonNode.Parse(text)!.AsObject();
        node.Remove("scene");
        return node.ToJsonString();
    }

    private static IEnumerable<XElement> WithClass(XDocument doc, string cls) => doc.Descendants().Where(e => Classes(e).Contains(cls));

    private static string[] Classes(XElement e) => ((string?)e.Attribute("class") ?? string.Empty).Split(' ', StringSplitOptions.RemoveEmptyEntries);

    private static double Attr(XElement e, string name) => double.Parse((string)e.Attribute(name)!, CultureInfo.InvariantCulture);
}
