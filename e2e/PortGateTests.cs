using System.Text.RegularExpressions;
using AcPhys.E2E.Support;
using AcPhys.Spec.Invariants;

namespace AcPhys.E2E;

/// <summary>
/// The gate as a port's xunit tests (AcPhys.Xunit) gives <c>acphys verify --impl</c>'s verdicts on the same adapter:
/// the example port (examples/dotnet-port), clean and with each seeded bug, through <c>dotnet test</c> of its gate
/// tests and through verify — the same invariants pass, fail and are skipped, and each failing test's message holds
/// verify's failure block verbatim, replay lines included.
/// </summary>
[Collection(PortGateCollection.Name)]
public sealed partial class PortGateTests
{
    public static TheoryData<string> Bugs => ["none", "clamp-106", "trunc", "edge-off-by-one", "inbound-x-only"];

    [Theory(DisplayName = "PORT-GATE: dotnet test on the port's gate tests fails, passes and skips exactly the invariants acphys verify --impl does")]
    [MemberData(nameof(Bugs))]
    public void GateTests_GiveVerifysVerdictsAndFailureText(string bug)
    {
        string folder = Path.Combine(Path.GetTempPath(), "acphys-e2e-port-gate-" + bug);
        if (Directory.Exists(folder))
        {
            Directory.Delete(folder, recursive: true);
        }

        var environment = new Dictionary<string, string> { ["ACPHYS_FAILURES"] = Path.Combine(folder, "failures") };
        if (bug != "none")
        {
            environment["ACPHYS_PORT_BUG"] = bug;
        }

        var verify = Acphys.Run(["verify", "--impl", GateTestRun.ExamplePortDll], environment);
        Assert.True(verify.Exit == (bug == "none" ? 0 : 1), verify.ToString());
        string trx = Path.Combine(folder, "gate.trx");
        var (test, rows) = GateTestRun.Dotnet(["test", GateTestRun.ExampleGateDll, "--logger", "trx;LogFileName=" + trx], trx, environment);
        Assert.True(test.Exit == (bug == "none" ? 0 : 1), test.ToString());

        var failed = FailLine().Matches(verify.Out).Select(m => m.Groups[1].Value).ToHashSet();
        var notTested = NotTestedLine().Matches(verify.Out).ToDictionary(m => m.Groups[1].Value, m => m.Groups[2].Value.TrimEnd());
        var gate = rows.Where(r => r.Name.Contains(".Holds(", StringComparison.Ordinal)).ToDictionary(r => IdOf(r.Name));
        Assert.Equal(InvariantCatalogue.All.Count, gate.Count);
        Assert.Equal(bug == "none", failed.Count == 0);
        Assert.Equal(failed.Order(), gate.Where(g => g.Value.Outcome == "Failed").Select(g => g.Key).Order());
        Assert.Equal(notTested.Keys.Order(), gate.Where(g => g.Value.Outcome == "NotExecuted").Select(g => g.Key).Order());
        foreach (var (id, reason) in notTested)
        {
            Assert.Contains(reason, gate[id].Text, StringComparison.Ordinal);
        }

        foreach (string id in failed)
        {
            string block = Block(verify.Out, id);
            Assert.Contains("  replay     acphys verify --only " + id + " ", block, StringComparison.Ordinal);
            Assert.Contains("--impl " + GateTestRun.ExamplePortDll, block, StringComparison.Ordinal);
            Assert.Contains(block, gate[id].Text.ReplaceLineEndings("\n"), StringComparison.Ordinal);
        }

        Assert.Single(rows, r => r.Name.EndsWith(".TestsAtLeastMinTested", StringComparison.Ordinal) && r.Outcome == "Passed");
    }

    [Fact(DisplayName = "PORT-GATE: a port testing fewer invariants than its floor (ACPHYS_MIN_TESTED, as verify --min-tested) fails the gate tests with a clear message; a malformed floor is named")]
    public void GateTests_FailUnderTheFloor()
    {
        string folder = Path.Combine(Path.GetTempPath(), "acphys-e2e-port-gate-floor");
        string trx = Path.Combine(folder, "floor.trx");
        string[] args = ["test", GateTestRun.ExampleGateDll, "--filter", "FullyQualifiedName~TestsAtLeastMinTested", "--logger", "trx;LogFileName=" + trx];
        var (under, rows) = GateTestRun.Dotnet(args, trx, new Dictionary<string, string> { ["ACPHYS_MIN_TESTED"] = "30" });
        Assert.True(under.Exit == 1, under.ToString());
        var row = Assert.Single(rows);
        Assert.Equal("Failed", row.Outcome);
        Assert.Contains($"not a pass: 23 of {InvariantCatalogue.All.Count} invariants tested, fewer than the floor 30 (ACPHYS_MIN_TESTED); example-port announces blockid_to_lcoord,", row.Text, StringComparison.Ordinal);
        Assert.Contains("not tested: ", row.Text, StringComparison.Ordinal);

        File.Delete(trx);
        var (malformed, bad) = GateTestRun.Dotnet(args, trx, new Dictionary<string, string> { ["ACPHYS_MIN_TESTED"] = "lots" });
        Assert.True(malformed.Exit == 1, malformed.ToString());
        Assert.Contains($"ACPHYS_MIN_TESTED='lots' must be a whole number from 1 to {InvariantCatalogue.All.Count}", Assert.Single(bad).Text, StringComparison.Ordinal);
    }

    // verify's block of one failure: from its FAIL line to the line before the next blank line.
    private static string Block(string output, string id)
    {
        string text = output.ReplaceLineEndings("\n");
        int start = text.IndexOf("\nFAIL " + id + " on ", StringComparison.Ordinal) + 1;
        Assert.True(start > 0, "no FAIL block for " + id);
        int end = text.IndexOf("\n\n", start, StringComparison.Ordinal);
        return text[start..(end < 0 ? text.Length : end)];
    }

    private static string IdOf(string testName) => IdInName().Match(testName) is { Success: true } m ? m.Groups[1].Value : testName;

    [GeneratedRegex(@"^FAIL (\S+) on ", RegexOptions.Multiline)]
    private static partial Regex FailLine();

    [GeneratedRegex(@"^NOT TESTED (\S+): (.*)$", RegexOptions.Multiline)]
    private static partial Regex NotTestedLine();

    [GeneratedRegex("invariant: \"([^\"]+)\"")]
    private static partial Regex IdInName();
}
