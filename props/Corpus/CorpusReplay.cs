using AcPhys.Contract;
using AcPhys.Formats.Corpus;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using Xunit.Abstractions;

namespace AcPhys.Props.Corpus;

/// <summary>Every stored case replays: it parses, every invariant holds on it against the reference, and every fault it names is caught by it.</summary>
public sealed class CorpusReplay(ITestOutputHelper output)
{
    public static TheoryData<string> Files
    {
        get
        {
            var data = new TheoryData<string>();
            foreach (var f in Directory.EnumerateFiles(RepoPaths.Corpus, "*.json", SearchOption.AllDirectories).Order(StringComparer.Ordinal))
            {
                data.Add(Path.GetRelativePath(RepoPaths.Root, f));
            }

            return data;
        }
    }

    [Fact(DisplayName = "corpus/ holds seeds to replay")]
    public void CorpusIsNotEmpty() => Assert.True(Files.Count >= 10, $"only {Files.Count} corpus files");

    [Theory(DisplayName = "Corpus case: every invariant holds on the reference and every named fault is caught")]
    [MemberData(nameof(Files))]
    public void Replays(string relativePath)
    {
        var entry = CorpusJson.ReadFile(Path.Combine(RepoPaths.Root, relativePath));
        output.WriteLine($"{entry.Title}: {(object?)entry.Walk ?? entry.Case}");
        if (entry.Invariant is not null)
        {
            Assert.NotNull(InvariantCatalogue.Find(entry.Invariant));
        }

        var violation = InvariantCatalogue.CheckEntry(ReferenceAdapter.Instance, entry);
        Assert.Null(violation);
        foreach (var faultId in entry.Catches)
        {
            Assert.NotNull(PlantedFaults.Find(faultId));
            var caught = InvariantCatalogue.CheckEntry(PlantedFaults.Create(faultId), entry);
            output.WriteLine($"  {faultId}: {caught}");
            Assert.NotNull(caught);
        }
    }

    [Theory(DisplayName = "Corpus files round-trip through CorpusJson bit for bit")]
    [MemberData(nameof(Files))]
    public void RoundTrips(string relativePath)
    {
        var entry = CorpusJson.ReadFile(Path.Combine(RepoPaths.Root, relativePath));
        string text = CorpusJson.Write(entry);
        var again = CorpusJson.Read(text, "rewritten");
        Assert.Equal(text, CorpusJson.Write(again)); // floats are written in round-trip form, so equal text is equal bits
        Assert.Equal(entry.Catches, again.Catches);
    }
}
