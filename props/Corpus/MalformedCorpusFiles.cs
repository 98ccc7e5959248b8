using AcPhys.Formats;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Props.Support;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Corpus;

/// <summary>Bad corpus files are refused whole, with the file, the JSON path and what is wrong; never a stack trace or a half-read entry.</summary>
public sealed class MalformedCorpusFiles
{
    private const string Good = """
        {"format":"acphys-case","version":1,"kind":"land","title":"t","foundBy":"hand","catches":[],
         "case":{"cell":"0xA9B40031","x":150,"y":-0.5,"lcoord":[1,2]}}
        """;

    public static TheoryData<string, string> Cases => new()
    {
        { "{", "not valid JSON" },
        { "[]", "$: expected an object" },
        { Good.Replace("acphys-case", "other", StringComparison.Ordinal), "$.format: expected \"acphys-case\"" },
        { Good.Replace("\"version\":1", "\"version\":2", StringComparison.Ordinal), "$.version: expected 1" },
        { Good.Replace("\"kind\":\"land\"", "\"kind\":\"scene\"", StringComparison.Ordinal), "$.kind: expected \"land\" or \"walk\"" },
        { Good.Replace("\"kind\":\"land\"", "\"kind\":\"walk\"", StringComparison.Ordinal), "$.walk: missing" },
        { Good.Replace("\"title\":\"t\",", string.Empty, StringComparison.Ordinal), "$.title: missing" },
        { Good.Replace("\"foundBy\":\"hand\"", "\"foundBy\":\"me\"", StringComparison.Ordinal), "$.foundBy: expected hand, props, fuzz, spec, diff, verify or capture" },
        { Good.Replace("\"catches\":[]", "\"catches\":\"x\"", StringComparison.Ordinal), "$.catches: expected an array of fault ids" },
        { Good.Replace("\"catches\":[]", "\"catches\":[1]", StringComparison.Ordinal), "$.catches[0]: expected a string" },
        { Good.Replace("\"case\":{", "\"case\":[{", StringComparison.Ordinal).Replace("]}}", "]}]}", StringComparison.Ordinal), "$.case: expected an object" },
        { Good.Replace("0xA9B40031", "A9B40031", StringComparison.Ordinal), "$.case.cell: expected \"0x\" and 8 hex digits" },
        { Good.Replace("\"x\":150", "\"x\":\"150\"", StringComparison.Ordinal), "$.case.x: expected a number or \"NaN\"" },
        { Good.Replace("\"x\":150", "\"x\":true", StringComparison.Ordinal), "$.case.x: expected a number" },
        { Good.Replace("\"x\":150", "\"x\":1e39", StringComparison.Ordinal), "$.case.x: number overflows float32" },
        { Good.Replace("\"y\":-0.5,", string.Empty, StringComparison.Ordinal), "$.case.y: missing" },
        { Good.Replace("[1,2]", "[1]", StringComparison.Ordinal), "$.case.lcoord: expected [x, y]" },
        { Good.Replace("[1,2]", "[1.5,2]", StringComparison.Ordinal), "$.case.lcoord[0]: expected a 32-bit integer" },
        { Good.Replace("[1,2]", "[1,99999999999]", StringComparison.Ordinal), "$.case.lcoord[1]: expected a 32-bit integer" },
        { Good.Replace("\"catches\":[]", "\"mode\":[],\"catches\":[]", StringComparison.Ordinal), "$.mode: expected an object" }, // issue 41: the mode a case was found in
        { Good.Replace("\"catches\":[]", "\"mode\":{\"fidelty\":[]},\"catches\":[]", StringComparison.Ordinal), "$.mode.fidelty: unknown field (known: pick, fidelity, fault)" },
        { Good.Replace("\"catches\":[]", "\"mode\":{\"pick\":\"retail\"},\"catches\":[]", StringComparison.Ordinal), "$.mode.pick: expected \"current-first\"" },
        { Good.Replace("\"catches\":[]", "\"mode\":{\"pick\":1},\"catches\":[]", StringComparison.Ordinal), "$.mode.pick: expected a string" },
        { Good.Replace("\"catches\":[]", "\"mode\":{\"fidelity\":[]},\"catches\":[]", StringComparison.Ordinal), "$.mode.fidelity: expected an array of 1 to 16 deviation names" },
        { Good.Replace("\"catches\":[]", "\"mode\":{\"fidelity\":[2]},\"catches\":[]", StringComparison.Ordinal), "$.mode.fidelity[0]: expected a string" },
        { Good.Replace("\"catches\":[]", "\"mode\":{\"fidelity\":[\"ace-stale\"]},\"catches\":[]", StringComparison.Ordinal), "$.mode.fidelity: unknown deviation \"ace-stale\"" },
        { Good.Replace("\"catches\":[]", "\"mode\":{\"fault\":\"\"},\"catches\":[]", StringComparison.Ordinal), "$.mode.fault: expected a planted fault id" },
        { Good.Replace("\"kind\":\"land\",", "\"kind\":\"land\",\"kind\":\"walk\",", StringComparison.Ordinal), "$.kind: duplicate key \"kind\"" }, // once "$.walk: missing"
        { Good.Replace("\"x\":150", "\"x\":150,\"x\":151", StringComparison.Ordinal), "$.case.x: duplicate key \"x\"" }, // once the last won
        { Good.Replace("\"title\":\"t\"", "\"\\ud800\":1,\"title\":\"t\"", StringComparison.Ordinal), "$.<name>: not valid text" }, // once InvalidOperationException from the duplicate-key search
        { Good.Replace("\"title\":\"t\"", "\"title\":\"" + new string('t', 5000) + "\"", StringComparison.Ordinal), "$.title: 5000 characters; at most 4096" }, // once echoed whole
    };

    [Fact(DisplayName = "The well-formed sample parses (so each malformed variant differs by one defect)")]
    public void GoodSampleParses() => Assert.Equal(-0.5f, CorpusJson.Read(Good, "good.json").Case!.Value.Y);

    [Theory(DisplayName = "A malformed corpus file is refused with its JSON path and the problem")]
    [MemberData(nameof(Cases))]
    public void Refused(string json, string expected)
    {
        var e = Assert.Throws<InputFormatException>(() => CorpusJson.Read(json, "bad.json"));
        Assert.StartsWith("bad.json: ", e.Message, StringComparison.Ordinal);
        Assert.Contains(expected, e.Message, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "A missing file is a InputFormatException naming the file")]
    public void MissingFile()
    {
        var e = Assert.Throws<InputFormatException>(() => CorpusJson.ReadFile("/nonexistent/acphys.json"));
        Assert.Contains("/nonexistent/acphys.json", e.Message, StringComparison.Ordinal);
    }

    [CiProperty(MaxTest = 2000, DisplayName = "Any text either parses or raises InputFormatException, nothing else (mangled good files)")]
    public Property MangledTextNeverThrowsAnythingElse() =>
        Prop.ForAll(Gen.Zip(Gen.Choose(0, Good.Length - 1), Gen.Choose(0, 127)).ToArbitrary(), t =>
            {
                var chars = Good.ToCharArray();
                chars[t.Item1] = (char)t.Item2;
                try
                {
                    _ = CorpusJson.Read(new string(chars), "mangled.json");
                }
                catch (InputFormatException)
                {
                }
            });

    [CiProperty(MaxTest = 2000, DisplayName = "Written entries read back to the same case for generated cases (NaN, -0, subnormals included)")]
    public Property WriteReadRoundTrips() =>
        Prop.ForAll(LandGens.Cases.ToArbitrary(), c =>
            {
                var entry = new CorpusEntry { Title = "t", FoundBy = "props", Case = c };
                LandCase back = CorpusJson.Read(CorpusJson.Write(entry), "rt").Case!.Value;
                return back.Cell == c.Cell && back.Lcoord == c.Lcoord
                    && BitConverter.SingleToInt32Bits(back.X) == BitConverter.SingleToInt32Bits(c.X)
                    && BitConverter.SingleToInt32Bits(back.Y) == BitConverter.SingleToInt32Bits(c.Y);
            });

    [Theory(DisplayName = "The mode a case was found in (pick, fidelity, fault) is written and read back unchanged; retail writes no mode field (issue 41)")]
    [InlineData("current-first", "", null)]
    [InlineData(null, "ace-keeps-stale-cells", null)]
    [InlineData(null, "ace,double", "close-is-outside")]
    [InlineData(null, "", null)]
    public void ModeRoundTrips(string? pick, string fidelity, string? fault)
    {
        var mode = new CaseMode(pick, fidelity.Length == 0 ? [] : fidelity.Split(','), fault);
        var entry = new CorpusEntry { Title = "t", FoundBy = "verify", Mode = mode, Case = new LandCase(new AcPhys.Core.CellId(0xA9B40031), 1, 2, new AcPhys.Core.Lcoord(1, 2)) };
        string text = CorpusJson.Write(entry);
        var back = CorpusJson.Read(text, "rt");
        Assert.Equal(mode.IsRetail ? null : mode, back.Mode);
        Assert.Equal(!mode.IsRetail, text.Contains("\"mode\"", StringComparison.Ordinal));
        Assert.NotEqual(FailureFile.NameFor(entry), FailureFile.NameFor(entry with { Mode = new CaseMode("current-first", ["double"], "x") }));
    }

    [Fact(DisplayName = "AtomicFile leaves no temp file behind and replaces the target whole")]
    public void AtomicWrite()
    {
        string dir = Path.Combine(Path.GetTempPath(), "acphys-atomic-" + Guid.NewGuid().ToString("N"));
        try
        {
            string path = Path.Combine(dir, "a.json");
            AtomicFile.WriteAllText(path, "one");
            AtomicFile.WriteAllText(path, "two");
            Assert.Equal("two", File.ReadAllText(path));
            Assert.Single(Directory.GetFiles(dir));
        }
        finally
        {
            Directory.Delete(dir, recursive: true);
        }
    }
}
