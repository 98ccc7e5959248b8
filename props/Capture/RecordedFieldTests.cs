using AcPhys.Formats;
using AcPhys.Formats.Corpus;
using AcPhys.Props.Support;

namespace AcPhys.Props.Capture;

/// <summary>
/// RECORDED-FIELD: the optional <c>recorded</c> array of a walk file is strictly validated, round-trips, and is purely
/// additive — a stored walk without it is read and re-written exactly as before.
/// </summary>
public sealed class RecordedFieldTests
{
    private const string Walk = "{\"format\":\"acphys-case\",\"version\":1,\"kind\":\"walk\",\"title\":\"t\",\"foundBy\":\"capture\",\"catches\":[],"
        + "\"walk\":{\"start\":{\"cell\":\"0xA9B40031\",\"x\":150,\"y\":0.125,\"z\":0},\"body\":[{\"x\":0,\"y\":0,\"z\":0,\"r\":0.48}],\"steps\":[[0,-0.25]]}";

    public static TheoryData<string, string> Malformed => new()
    {
        { ",\"recorded\":[{\"cell\":\"0xA9B40031\"}]}", "1 recorded answers for a walk of 2 queries" },
        { ",\"recorded\":[{\"cell\":\"0xA9B40031\"},{\"cell\":\"0xA9B40031\",\"why\":1}]}", "$.recorded[1].why: unknown field" },
        { ",\"recorded\":[{\"cell\":\"0xA9B40031\"},{\"cell\":\"A9B4\"}]}", "$.recorded[1].cell: expected \"0x\" and 8 hex digits" },
        { ",\"recorded\":[{\"cell\":\"0xA9B40031\"},{}]}", "$.recorded[1]" },
        { ",\"recorded\":[{\"cell\":\"0xA9B40031\",\"cells\":[\"0xA9B40031\",7]},{\"cell\":\"0xA9B40031\"}]}", "$.recorded[0].cells[1]" },
        { ",\"recorded\":{}}", "$.recorded: expected an array" },
    };

    [Theory(DisplayName = "RECORDED-FIELD: a malformed recorded array is refused with its JSON path")]
    [MemberData(nameof(Malformed))]
    public void Refused(string tail, string expected)
    {
        var e = Assert.Throws<InputFormatException>(() => CorpusJson.Read(Walk + tail, "f.json"));
        Assert.Contains(expected, e.Message, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "RECORDED-FIELD: only a walk records answers")]
    public void OnlyWalks()
    {
        string land = "{\"format\":\"acphys-case\",\"version\":1,\"kind\":\"land\",\"title\":\"t\",\"foundBy\":\"hand\",\"case\":{\"cell\":\"0xA9B40031\",\"x\":1,\"y\":1,\"lcoord\":[0,0]},\"recorded\":[]}";
        Assert.Contains("$.recorded: only a walk", Assert.Throws<InputFormatException>(() => CorpusJson.Read(land, "f.json")).Message, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "RECORDED-FIELD: recorded answers round-trip, and without them the file is written exactly as the same entry with none")]
    public void RoundTripsAndIsAdditive()
    {
        var entry = CorpusJson.Read(Walk + ",\"recorded\":[{\"cell\":\"0xA9B40031\",\"cells\":[\"0xA9B40031\",\"0xA9B30038\"]},{\"cell\":\"0xA9B40031\"}]}", "f.json");
        string text = CorpusJson.Write(entry);
        var again = CorpusJson.Read(text, "again");
        Assert.Equal(text, CorpusJson.Write(again));
        Assert.Equal(2, again.Recorded!.Count);
        Assert.Equal(2, again.Recorded[0].Cells!.Count);
        Assert.Null(again.Recorded[1].Cells);
        string without = CorpusJson.Write(entry with { Recorded = null });
        int at = text.IndexOf(",\n  \"recorded\"", StringComparison.Ordinal);
        Assert.True(at > 0);
        Assert.Equal(without, text[..at] + "\n}\n");
    }

    [Fact(DisplayName = "RECORDED-FIELD: every stored walk file reads with no recorded answers and re-writes without the field")]
    public void StoredWalksUnchanged()
    {
        var walks = Directory.EnumerateFiles(RepoPaths.Corpus, "*.json", SearchOption.AllDirectories)
            .Select(f => CorpusJson.ReadFile(f)).Where(e => e.Walk is not null).ToList();
        Assert.NotEmpty(walks);
        Assert.All(walks, e => Assert.Null(e.Recorded));
        Assert.All(walks, e => Assert.DoesNotContain("\"recorded\"", CorpusJson.Write(e), StringComparison.Ordinal));
    }
}
