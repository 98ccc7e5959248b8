using AcPhys.Contract;
using AcPhys.Formats;
using AcPhys.Formats.Corpus;
using AcPhys.Fuzz.Targets;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using Xunit;

namespace AcPhys.Fuzz.Tests;

/// <summary>The <c>parts</c> target: its codec, its checks under the two parts faults, the <c>parts</c> corpus kind and the triage of its crashes.</summary>
public sealed class PartsTargetTests
{
    // One box 2 m short of block 0x80's east line, 5.4 m half wide: it reaches 3.4 m into block 0x81.
    private const string AcrossTheEastLine = "0080800808c0008000000000992020";

    // Two small boxes in block 0x80, the second in another cell (12, 12) and (180, 180): one anchor each under ACE.
    private const string TwoCellsApart = "018080000010001000000000101010" + "0000f000f000000000101010";

    // A valid part, edited by the reader tests.
    private const string PartJson = "{\"cell\": \"0x80800001\", \"origin\": {\"x\": 10, \"y\": 10, \"z\": 0.5}, \"rotation\": {\"w\": 1, \"x\": 0, \"y\": 0, \"z\": 0}, "
        + "\"min\": {\"x\": -1, \"y\": -1, \"z\": -1}, \"max\": {\"x\": 1, \"y\": 1, \"z\": 1}, \"radius\": 1, \"always2d\": false}";

    // corpus/fuzz/parts: near the east block line, at a block corner, two parts by the north line.
    private static readonly string[] HandMadeSeeds = ["6d0c264cccc70c5e", "db84c11d8bcc730f", "1eb6f8dec8fcd03a"];

    private static readonly PartsTarget Target = (PartsTarget)FuzzTargets.Find("parts")!;

    [Fact]
    public void Any_bytes_decode_to_a_bounded_parts_query_that_holds_on_the_correct_core()
    {
        // PARTS-COVERAGE, PARTS-SOUNDNESS: random, empty, all-ones and a megabyte decode without an exception to 1–4
        // finite parts, and break no parts invariant on the reference.
        var inputs = CodecInputs.Edges(PartsCodec.Length, 400, seed: 17);

        foreach (var input in inputs)
        {
            var c = Target.Decode(input);
            Assert.InRange(c.Parts.Count, 1, PartsCodec.MaxParts);
            Assert.All(c.Parts, p => Assert.True(float.IsFinite(p.Frame.Origin.X + p.Frame.Origin.Y + p.Bounds.Max.X + p.Bounds.Max.Y + p.Radius)));
            Assert.Null(Target.Classify(input, fault: null));
        }
    }

    [Fact]
    public void Line_mode_reaches_the_block_lines_and_a_neighbouring_block_frame()
    {
        // The codec's line form puts an origin on a block line (0 or 192) or within 4 m of it, and flag bits 5–7 move
        // a part into a neighbouring block's frame: the placements the parts faults are about.
        var onLine = Target.Decode(Convert.FromHexString("00808018080008000000000000"));
        Assert.Equal(192f, onLine.Parts[0].Frame.Origin.X);
        Assert.Equal(192f, onLine.Parts[0].Frame.Origin.Y);
        var neighbour = Target.Decode(Convert.FromHexString("008080200000"));
        Assert.Equal(0x81, neighbour.Parts[0].Cell.BlockX);
        Assert.Equal(0x80, neighbour.Parts[0].Cell.BlockY);
    }

    [Theory]
    [InlineData("ace-same-block-guard", AcrossTheEastLine)]
    [InlineData("ace-every-part-anchors", TwoCellsApart)]
    public void A_known_input_breaks_the_invariant_that_catches_the_parts_fault(string fault, string hex)
    {
        // The test throws the typed violation with the ID the catalogue reports first, one the fault is documented to
        // break; the correct core passes the same input.
        byte[] input = Convert.FromHexString(hex);
        var expected = InvariantCatalogue.CheckParts(PlantedFaults.Create(fault), Target.Decode(input));
        Assert.NotNull(expected);
        Assert.Contains(expected.InvariantId, PlantedFaults.Find(fault)!.CaughtBy);

        var thrown = Assert.Throws<InvariantViolationException>(() => Target.CreateTest(fault)(input));

        Assert.Equal(expected.InvariantId, thrown.Violation.InvariantId);
        Assert.Equal(expected.InvariantId, Target.Classify(input, fault)!.Key);
        Target.CreateTest(fault: null)(input);
    }

    [Fact]
    public void The_seeds_hold_on_the_correct_core_and_the_hand_made_ones_under_both_parts_faults()
    {
        // Seeds that already fail would make a find the seeds' doing, not the fuzzer's. The files correct-core
        // campaigns add to corpus/fuzz/parts (coverage growth) need only hold on the correct core.
        string folder = Path.Combine(RepoPaths.Root, "corpus", "fuzz", "parts");
        var handMade = Target.Seeds.Values.Concat(HandMadeSeeds.Select(n => File.ReadAllBytes(Path.Combine(folder, n)))).ToList();
        foreach (var seed in handMade)
        {
            Assert.Null(Target.Classify(seed, "ace-same-block-guard"));
            Assert.Null(Target.Classify(seed, "ace-every-part-anchors"));
        }

        Assert.All(handMade.Concat(Directory.GetFiles(folder).Select(File.ReadAllBytes)), seed => Assert.Null(Target.Classify(seed, fault: null)));
    }

    [Theory]
    [InlineData("ace-same-block-guard", AcrossTheEastLine)]
    [InlineData("ace-every-part-anchors", TwoCellsApart)]
    public void A_parts_crash_is_shrunk_to_a_parts_regression_that_replays(string fault, string hex)
    {
        var finding = Target.Classify(Convert.FromHexString(hex), fault)!;

        var entry = Target.Minimise(finding, fault, "test")!;
        string path = Path.Combine(Path.GetTempPath(), $"acphys-parts-{Environment.ProcessId}-{FailureFile.NameFor(entry)}");
        AtomicFile.WriteAllText(path, CorpusJson.Write(entry));
        var read = CorpusJson.ReadFile(path);
        File.Delete(path);

        Assert.Equal("parts", read.Kind);
        Assert.Equal(finding.Key, read.Invariant);
        Assert.Equal([fault], read.Catches);
        Assert.Equal(CorpusJson.Write(entry), CorpusJson.Write(read)); // the file round-trips bit for bit
        Assert.Equal(finding.Key, InvariantCatalogue.CheckEntry(PlantedFaults.Create(fault), read)?.InvariantId);
        Assert.Null(InvariantCatalogue.CheckEntry(ReferenceAdapter.Instance, read));
        Assert.StartsWith(finding.Key + "-", FailureFile.NameFor(entry), StringComparison.Ordinal);
        Assert.NotEqual(finding.Case!.ToString(), read.Parts!.ToString()); // shrunk (origin, box or radius made simpler)
    }

    [Theory]
    [InlineData("\"parts\": []", "$.parts: expected an array of 1 to")]
    [InlineData("\"parts\": [{\"cell\": \"0x80800001\"}]", "$.parts[0].origin: missing")]
    [InlineData("\"parts\": [" + PartJson + "]", null)]
    [InlineData("\"parts\": [" + PartJson + "]", "$.parts[0].always2d: expected true or false", "false", "\"no\"")]
    [InlineData("\"parts\": [" + PartJson + "]", "$.parts[0].rotation: expected a unit quaternion", "\"w\": 1", "\"w\": 2")]
    [InlineData("\"parts\": [" + PartJson + "]", "$.parts[0].radius: radius must be finite", "\"radius\": 1", "\"radius\": \"NaN\"")]
    [InlineData("\"parts\": [" + PartJson + "]", "$.parts[0].min: every component", "\"x\": -1", "\"x\": 3")]
    [InlineData("\"walk\": {}", "$.parts: missing")]
    public void The_parts_reader_is_strict_and_says_where(string body, string? error, string? from = null, string? to = null)
    {
        string json = "{\"format\": \"acphys-case\", \"version\": 1, \"kind\": \"parts\", \"title\": \"t\", \"foundBy\": \"hand\", " + body + "}";
        if (from is not null)
        {
            json = json.Replace(from, to, StringComparison.Ordinal);
        }

        if (error is null)
        {
            Assert.Single(CorpusJson.Read(json, "p.json").Parts!.Parts);
            return;
        }

        var e = Assert.Throws<InputFormatException>(() => CorpusJson.Read(json, "p.json"));
        Assert.Contains(error, e.Message, StringComparison.Ordinal);
    }
}
