using AcPhys.Formats.Corpus;
using AcPhys.Props.Support;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Judging;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The known-bug catalogue (mutation/known-bugs/, docs/bite.md): its conventions, and the fast CI bite check that
/// every catalogue bug is caught by every invariant it declares, under the test profile (pr in CI).
/// </summary>
public sealed class KnownBugCatalogueTests(ITestOutputHelper output)
{
    // A fault that keeps state between calls fails by its history (no-reset: the previous query's cells stay in the
    // array), which no case file holds: its file must still replay to a violation, but not necessarily of the same invariant.
    private static readonly string[] KeepsState = [PlantedFaults.NoReset.Id];

    public static TheoryData<string> AvailableBugIds => new(KnownBugCatalogue.All.Where(b => b.IsAvailable).Select(b => b.Id));

    private static string Folder => Path.Combine(RepoPaths.Root, "mutation", "known-bugs");

    [Fact(DisplayName = "BITE-CATALOGUE: at least 15 entries, and the embedded catalogue is exactly the files of mutation/known-bugs/ (each parses, id = file name)")]
    public void CatalogueMatchesItsFiles()
    {
        // Ordered by id as the catalogue is ("no-hysteresis" before "no-hysteresis-indoor"; file names sort the other way).
        var onDisk = Directory.GetFiles(Folder, "*.json")
            .Select(f => KnownBugCatalogue.Parse(Path.GetFileName(f), File.ReadAllText(f))).OrderBy(b => b.Id, StringComparer.Ordinal).ToList();
        Assert.True(onDisk.Count >= 15, $"the catalogue has {onDisk.Count} entries; issue #5 asks for at least 15");
        Assert.Equal(onDisk.Select(b => b.Id), KnownBugCatalogue.All.Select(b => b.Id));
        Assert.All(onDisk, b => Assert.Equal(b with { CaughtBy = [] }, KnownBugCatalogue.Find(b.Id)! with { CaughtBy = [] }));
        Assert.All(onDisk, b => Assert.Equal(b.CaughtBy, KnownBugCatalogue.Find(b.Id)!.CaughtBy));
    }

    [Fact(DisplayName = "BITE-CATALOGUE: every wired entry names an existing planted fault and existing invariant IDs; a pending entry's fault does not exist yet or nothing catches it yet")]
    public void EntriesNameExistingFaultsAndInvariants()
    {
        foreach (var bug in KnownBugCatalogue.All)
        {
            if (bug.PendingOn is null)
            {
                Assert.True(bug.IsAvailable, $"{bug.Id}: {bug.NotAvailableReason}");
                var unknown = bug.CaughtBy.Where(id => InvariantCatalogue.Find(id) is null).ToList();
                Assert.True(unknown.Count == 0, $"{bug.Id}: unknown invariant(s) {string.Join(", ", unknown)} (see: acphys invariants)");
            }
            else
            {
                // Once the fault lands and something catches it (branch merged, CaughtBy filled in), the entry must be wired:
                // drop pendingOn. A fault that exists but no invariant catches on today's scenes has an empty CaughtBy.
                Assert.True(bug.PlantedFault is null || bug.PlantedFault.CaughtBy.Count == 0, $"{bug.Id}: fault '{bug.Fault}' now exists and is caught by {string.Join(", ", bug.PlantedFault?.CaughtBy ?? [])}; remove \"pendingOn\" from mutation/known-bugs/{bug.Id}.json");
            }
        }
    }

    [Fact(DisplayName = "BITE-CATALOGUE: every planted fault has a catalogue entry")]
    public void EveryPlantedFaultHasAnEntry()
    {
        var covered = KnownBugCatalogue.All.Select(b => b.Fault).ToHashSet(StringComparer.OrdinalIgnoreCase);
        var missing = PlantedFaults.All.Where(f => !covered.Contains(f.Id)).Select(f => f.Id).ToList();
        Assert.True(missing.Count == 0, "planted faults without a known-bug entry: " + string.Join(", ", missing));
    }

    [Fact(DisplayName = "BITE-CATALOGUE: the parser rejects a malformed entry with the file and the field named")]
    public void ParserNamesTheProblem()
    {
        const string good = """{"format":"acphys-known-bug","id":"x","title":"t","story":"s","source":"facts §1","fault":"trunc-floor"}""";
        Assert.Equal("trunc-floor", KnownBugCatalogue.Parse("x.json", good).Fault);
        Assert.Contains("id \"x\" must equal the file name", Assert.Throws<FormatException>(() => KnownBugCatalogue.Parse("y.json", good)).Message);
        Assert.Contains("caughtBy is not a field", Assert.Throws<FormatException>(() => KnownBugCatalogue.Parse("x.json", good.Replace("}", ",\"caughtBy\":[\"COVERAGE\"]}", StringComparison.Ordinal))).Message);
        Assert.Contains("unknown field \"extra\"", Assert.Throws<FormatException>(() => KnownBugCatalogue.Parse("x.json", good.Replace("}", ",\"extra\":1}", StringComparison.Ordinal))).Message);
        Assert.Contains("x.json: not valid JSON", Assert.Throws<FormatException>(() => KnownBugCatalogue.Parse("x.json", "{")).Message);
        Assert.Contains("x.json: title must be", Assert.Throws<FormatException>(() => KnownBugCatalogue.Parse("x.json", good.Replace("\"title\":\"t\",", string.Empty, StringComparison.Ordinal).Replace("trunc-floor", "no-such-fault", StringComparison.Ordinal))).Message);
    }

    [Fact(DisplayName = "BITE-CATALOGUE: an entry is derived from its planted fault: the catchers are the fault's, and a title or story the file leaves out is the fault's")]
    public void EntryIsDerivedFromItsFault()
    {
        var fault = PlantedFaults.TruncFloor;
        var bare = KnownBugCatalogue.Parse(fault.Id + ".json", $$"""{"format":"acphys-known-bug","id":"{{fault.Id}}","source":"facts §6.2"}""");
        Assert.Equal(fault.Id, bare.Fault);
        Assert.Equal(fault.CaughtBy, bare.CaughtBy);
        Assert.Equal(fault.Story, bare.Story);
        Assert.Equal(char.ToUpperInvariant(fault.Title[0]) + fault.Title[1..], bare.Title);
        var own = KnownBugCatalogue.Parse("y.json", $$"""{"format":"acphys-known-bug","id":"y","fault":"{{fault.Id}}","title":"T","story":"S","source":"s"}""");
        Assert.Equal(("T", "S", fault.Id), (own.Title, own.Story, own.Fault));
        Assert.Equal(fault.CaughtBy, own.CaughtBy);
    }

    [Fact(DisplayName = "BITE-PENDING: a bug whose fault does not exist is reported as pending with \"fault not available yet\", never run and never counted as caught")]
    public void PendingBugIsReportedNotRun()
    {
        var bug = new KnownBug("no-such-bug", "t", "s", "issue #5", "no-such-fault", ["COVERAGE"], "indoor");
        var report = BiteRunner.Run([bug], Profile.Pr);
        var row = Assert.Single(report.Bugs);
        Assert.Equal(BugStatus.Pending, row.Status);
        Assert.Empty(row.Cells);
        Assert.Empty(report.Escaped);
        Assert.StartsWith("fault not available yet", bug.NotAvailableReason, StringComparison.Ordinal);
        Assert.Contains("1 pending (fault not available yet)", BiteReportText.Summary(report), StringComparison.Ordinal);
        Assert.Contains("0 of 0 catalogue bugs caught", BiteReportText.Summary(report), StringComparison.Ordinal);
    }

    [Fact(DisplayName = "BITE-ESCAPE: a bug no run invariant catches is reported as escaped, in the summary, the markdown matrix and the JSON")]
    public void EscapedBugIsReported()
    {
        // no-hysteresis breaks only the pick; LCOORD-ROUNDTRIP cannot see it, ADJUST-RANGE holds too.
        var bug = new KnownBug("pick-only", "t", "s", "issue #5", "no-hysteresis", ["LCOORD-ROUNDTRIP", "ADJUST-RANGE"], null);
        var report = BiteRunner.Run([bug], Profile.Pr with { CasesPerInvariant = 500 }, seeds: 2, declaredOnly: true);
        var row = Assert.Single(report.Escaped);
        Assert.Equal([null, null], row.TimeToDetect);
        Assert.All(row.Cells, c => Assert.Equal(BiteVerdict.NotCaught, c.Verdict));
        Assert.Equal(["LCOORD-ROUNDTRIP", "ADJUST-RANGE"], row.MissedDeclared);
        Assert.Contains("0 of 1 catalogue bugs caught (0 %) under 2 seed(s)", BiteReportText.Summary(report), StringComparison.Ordinal);
        Assert.Contains("| `pick-only` | `no-hysteresis` | **ESCAPED** |", BiteReportText.Markdown(report, "acphys bite"), StringComparison.Ordinal);
        using var json = System.Text.Json.JsonDocument.Parse(BiteReportText.Json(report));
        Assert.Equal(1, json.RootElement.GetProperty("summary").GetProperty("escaped").GetInt32());
        Assert.Equal("escaped", json.RootElement.GetProperty("bugs")[0].GetProperty("status").GetString());
        Assert.Equal("not-caught", json.RootElement.GetProperty("bugs")[0].GetProperty("cells").GetProperty("ADJUST-RANGE").GetProperty("verdict").GetString());
    }

    [Fact(DisplayName = "BITE-STATEFUL: a stateful fault (no-reset) is caught under each of 5 bite seeds with a violation, never reported as a tool error")]
    public void StatefulFaultIsCaughtUnderEverySeed()
    {
        var impl = PlantedFaults.Create(PlantedFaults.NoReset.Id);
        var soundness = InvariantCatalogue.Find("SOUNDNESS")!;
        for (ulong k = 0; k < 5; k++)
        {
            var result = soundness.Run(impl, Profile.Pr.CasesPerInvariant, Seed.Derive(Profile.Pr.BaseSeed!.Value + k, soundness.Id), maxClasses: 1);
            Assert.Equal(ResultStatus.Failed, result.Status);
            Assert.NotNull(result.Violation);
            Assert.NotNull(result.TimeToFailure);
        }
    }

    [KnownBugsPendingFact(DisplayName = "BITE-PENDING: every catalogue entry has its planted fault (skipped, naming the entries, while some wait for another branch)")]
    public void NoEntryWaitsForAFault() =>
        Assert.All(KnownBugCatalogue.All, b => Assert.True(b.IsAvailable, $"{b.Id}: {b.NotAvailableReason}"));

    [Theory(DisplayName = "BITE: the catalogue bug is caught by every invariant it declares, under the test profile's seeds; REPLAY-REPRODUCES: each catcher's failure file, as verify writes it, replays to exit 1 naming that invariant")]
    [MemberData(nameof(AvailableBugIds))]
    public void CatalogueBugIsCaught(string bugId)
    {
        var bug = KnownBugCatalogue.Find(bugId)!;
        var report = BiteRunner.Run([bug], PropertyRun.Profile, declaredOnly: true);
        var row = Assert.Single(report.Bugs);
        output.WriteLine($"{bug.Id} ({bug.Title}): fault {bug.Fault}, profile {report.Profile.Name}, base seed {report.BaseSeed}");
        output.WriteLine($"caught by {string.Join(", ", row.CaughtBy)}; time to detect {BiteReportText.Ms(row.Median)}, cases {row.CasesToDetect[0]}");
        if (row.Example is { } e)
        {
            output.WriteLine($"shrunk: {e.Violation}");
            output.WriteLine($"replay: ./acphys verify --fault {bug.Fault} --only {e.InvariantId} --seed {e.Replay}");
        }

        Assert.True(row.Status == BugStatus.Caught, $"{bug.Id} ESCAPED: no declared invariant caught fault {bug.Fault}; replay: ./acphys bite --bug {bug.Id}");
        Assert.True(!row.MissedDeclared.Any(), $"{bug.Id}: declared catcher(s) {string.Join(", ", row.MissedDeclared)} did not catch it; replay: ./acphys verify --fault {bug.Fault} --only {string.Join(",", row.MissedDeclared)}");
        Assert.NotNull(row.Example);

        // Every failure found is a file that reproduces it where it is replayed (issue 25): the entry verify writes,
        // read back from its text, judged by the same judges acphys replay and render use, on a fresh faulty adapter.
        foreach (var cell in row.Cells.Where(c => c.Verdict == BiteVerdict.Caught))
        {
            var violation = Assert.IsType<Violation>(cell.Violation);
            var written = FailureFile.EntryFor(violation, FinderNames.Verify, "seed");
            Assert.True(written is not null, $"{bug.Id}: {cell.InvariantId}'s failure has no file form: {violation}");
            var entry = CorpusJson.Read(CorpusJson.Write(written), "failure file");
            var replay = CaseReplay.Of(entry, PlantedFaults.Create(bug.Fault));
            string line = $"./acphys replay artifacts/failures/{FailureFile.NameFor(entry)} --fault {bug.Fault}";
            Assert.True(replay.ExitCode == CaseReplay.Violated, $"{bug.Id}: {cell.InvariantId}'s failure file does not reproduce (exit {replay.ExitCode}); {line}; case {violation.CaseText}");
            Assert.True(KeepsState.Contains(bug.Fault) || replay.Run.Judgement.ViolatedIds.Contains(cell.InvariantId), $"{bug.Id}: {cell.InvariantId}'s failure file replays naming {string.Join(", ", replay.Run.Judgement.ViolatedIds)} only; {line}; case {violation.CaseText}");
            Assert.Equal(FinderNames.Verify, entry.FoundBy);
        }
    }
}
