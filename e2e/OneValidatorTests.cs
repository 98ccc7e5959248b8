using AcPhys.Contract;
using AcPhys.Formats;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Scenes;
using AcPhys.Protocol.Server;
using AcPhys.Spec.Scenes;

namespace AcPhys.E2E;

/// <summary>
/// One validator (issue 19): a protocol request to <c>serve</c> is refused for exactly what a corpus file is refused
/// for, with the same problem text (the rules live in formats/Values); the sphere-list rule is shared too (protocol queries may be empty, walk files need sphere 0).
/// </summary>
public sealed class OneValidatorTests
{
    private const string Request = """{"op":"outside_cells","cell":"0xA9B40031","spheres":[{"x":12,"y":Y,"z":0.5,"r":R}]}""";

    private const string WalkFile = """
        {"format":"acphys-case","version":1,"kind":"walk","title":"t","foundBy":"hand","catches":[],
         "walk":{"start":{"cell":"0xA9B40031","x":12,"y":Y,"z":0.5},"body":[{"x":0,"y":0,"z":0,"r":R}],"steps":[]}}
        """;

    /// <summary>Gets the values both readers must refuse, and the problem text both must give.</summary>
    public static TheoryData<string, string, string> Refused => new()
    {
        // y, r, problem text (without its location)
        { "1e39", "1", "number overflows float32" }, // serve once read +Infinity
        { "-1e39", "1", "number overflows float32" },
        { "12", "-1", "radius must be ≥ 0" }, // serve once answered for a negative radius
        { "12", "\"NaN\"", "radius must be finite" },
        { "12", "\"Infinity\"", "radius must be finite" },
        { "12", "true", "expected a number or \"NaN\"/\"Infinity\"/\"-Infinity\", got true" },
    };

    [Theory(DisplayName = "serve refuses what a corpus file refuses, with the same problem text")]
    [MemberData(nameof(Refused))]
    public void ServeAndCorpusRefuseAlike(string y, string r, string problem)
    {
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        string answer = server.Answer(Request.Replace("Y", y, StringComparison.Ordinal).Replace("R", r, StringComparison.Ordinal));
        Assert.StartsWith("{\"error\":\"malformed request: field \\\"spheres[0].", answer, StringComparison.Ordinal);
        Assert.Contains(problem.Replace("\"", "\\\"", StringComparison.Ordinal), answer, StringComparison.Ordinal);

        // The corpus file puts y on the walk's start and r on its body sphere: the same values, the same text.
        var e = Assert.Throws<InputFormatException>(() => CorpusJson.Read(WalkFile.Replace("Y", y, StringComparison.Ordinal).Replace("R", r, StringComparison.Ordinal), "bad.json"));
        Assert.Contains(problem, e.Message, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "A valid request and the same walk file are both accepted (each refusal above differs by one value)")]
    public void TheValidSampleIsAcceptedByBoth()
    {
        string answer = new ProtocolServer(ReferenceAdapter.Instance).Answer(Request.Replace("Y", "12", StringComparison.Ordinal).Replace("R", "1", StringComparison.Ordinal));
        Assert.StartsWith("{\"cells\":[", answer, StringComparison.Ordinal);
        Assert.Single(CorpusJson.Read(WalkFile.Replace("Y", "12", StringComparison.Ordinal).Replace("R", "1", StringComparison.Ordinal), "good.json").Walk!.Body);
    }

    [Fact(DisplayName = "An empty sphere list: a protocol query may be empty (it reads origin, issue 18), a walk file may not (sphere 0 is judged); one rule, one text")]
    public void EmptySphereListsFollowOneRule()
    {
        string answer = new ProtocolServer(ReferenceAdapter.Instance).Answer("""{"op":"outside_cells","cell":"0xA9B40031","spheres":[],"origin":{"x":12,"y":12,"z":0.5}}""");
        Assert.Equal("{\"cells\":[\"0xA9B40001\"]}", answer); // (12, 12) lies in cell 1 of block A9B4

        var e = Assert.Throws<InputFormatException>(() => CorpusJson.Read(WalkFile.Replace("[{\"x\":0,\"y\":0,\"z\":0,\"r\":R}]", "[]", StringComparison.Ordinal).Replace("Y", "12", StringComparison.Ordinal), "bad.json"));
        Assert.Contains("$.walk.body: expected an array of 1 to 10,000 spheres, got 0", e.Message, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "More spheres than the shared limit are refused by both")]
    public void TooManySpheresAreRefusedByBoth()
    {
        string many = string.Join(',', Enumerable.Repeat("""{"x":1,"y":1,"z":0,"r":1}""", 10_001));
        string answer = new ProtocolServer(ReferenceAdapter.Instance).Answer("{\"op\":\"outside_cells\",\"cell\":\"0xA9B40031\",\"spheres\":[" + many + "]}");
        Assert.Contains("expected an array of 0 to 10,000 spheres, got 10,001", answer, StringComparison.Ordinal);
        var e = Assert.Throws<InputFormatException>(() => CorpusJson.Read(WalkFile.Replace("[{\"x\":0,\"y\":0,\"z\":0,\"r\":R}]", "[" + many + "]", StringComparison.Ordinal).Replace("Y", "12", StringComparison.Ordinal), "bad.json"));
        Assert.Contains("expected an array of 1 to 10,000 spheres, got 10,001", e.Message, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "A scene file and a corpus file refuse a float32 overflow with the same text")]
    public void SceneFilesShareTheFloatRule()
    {
        string scene = SceneJson.Write(SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0.3f, 2, 6f, 6f, 5, true, true)));
        int d = scene.IndexOf("\"d\":", StringComparison.Ordinal);
        int end = scene.IndexOfAny([',', '}'], d);
        var e = Assert.Throws<InputFormatException>(() => SceneJson.Read(scene[..(d + 4)] + "1e39" + scene[end..], "bad.json"));
        Assert.Matches(@"bad\.json: \$\.\S+\.d: number overflows float32$", e.Message);
    }
}
