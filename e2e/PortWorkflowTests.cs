using System.Text.RegularExpressions;
using AcPhys.E2E.Support;
using AcPhys.Spec.Invariants;

namespace AcPhys.E2E;

/// <summary>
/// The PR workflow docs/ports.md gives a port's repository (section 13) does what it says on the .NET example: its
/// <c>Build</c> and <c>Gate</c> commands, read from the document's YAML, run on examples/dotnet-port/GateTests.
/// </summary>
[Collection(PortGateCollection.Name)]
public sealed partial class PortWorkflowTests
{
    [Fact(DisplayName = "PORT-WORKFLOW: the documented PR workflow's commands pass the clean example port and fail a seeded bug")]
    public void DocumentedWorkflow_PassesTheCleanPortAndFailsASeededBug()
    {
        var steps = WorkflowSteps();
        Assert.Equal(["Build", "Gate"], steps.Keys.Order());
        string work = Directory.CreateTempSubdirectory("acphys-e2e-workflow-").FullName;
        try
        {
            var environment = new Dictionary<string, string>
            {
                ["GATE_TESTS"] = Path.Combine(RepoPaths.Root, "examples", "dotnet-port", "GateTests"),
                ["ACPHYS_PROFILE"] = "pr",
                ["ACPHYS_FAILURES"] = Path.Combine(work, "failures"),
            };
            var build = Bash(steps["Build"], work, environment);
            Assert.True(build.Exit == 0, build.ToString());

            string trx = Path.Combine(work, "artifacts", "acphys", "gate.trx");
            var (gate, rows) = GateTestRun.Dotnet(["bash", "-c", steps["Gate"]], trx, environment, work, viaDotnet: false);
            Assert.True(gate.Exit == 0, gate.ToString());
            Assert.Equal(24, rows.Count(r => r.Outcome == "Passed"));
            Assert.Equal(InvariantCatalogue.All.Count - 23, rows.Count(r => r.Outcome == "NotExecuted")); // all but the 23 the port tests
            Assert.DoesNotContain(rows, r => r.Outcome == "Failed");

            File.Delete(trx);
            environment["ACPHYS_PORT_BUG"] = "inbound-x-only";
            var (bitten, bittenRows) = GateTestRun.Dotnet(["bash", "-c", steps["Gate"]], trx, environment, work, viaDotnet: false);
            Assert.True(bitten.Exit == 1, bitten.ToString());
            Assert.Equal(["LANDDEFS-CONFORMANCE", "MAP-EDGE"], bittenRows.Where(r => r.Outcome == "Failed").Select(r => IdInName().Match(r.Name).Groups[1].Value).Order());
        }
        finally
        {
            Directory.Delete(work, recursive: true);
        }
    }

    // The run lines of the named steps of the YAML block in docs/ports.md, section 13.
    private static Dictionary<string, string> WorkflowSteps()
    {
        string doc = File.ReadAllText(Path.Combine(RepoPaths.Root, "docs", "ports.md")).ReplaceLineEndings("\n");
        int section = doc.IndexOf("\n## 13. ", StringComparison.Ordinal);
        Assert.True(section > 0, "docs/ports.md has no section 13");
        int start = doc.IndexOf("```yaml\n", section, StringComparison.Ordinal);
        int end = doc.IndexOf("\n```", start + 1, StringComparison.Ordinal);
        return StepRun().Matches(doc[start..end]).ToDictionary(m => m.Groups[1].Value, m => m.Groups[2].Value.Trim());
    }

    private static Run Bash(string command, string folder, IReadOnlyDictionary<string, string> environment) =>
        GateTestRun.Dotnet(["bash", "-c", command], trx: null, environment, folder, viaDotnet: false).Run;

    [GeneratedRegex(@"- name: (Build|Gate)\n\s+run: (.+)")]
    private static partial Regex StepRun();

    [GeneratedRegex("invariant: \"([^\"]+)\"")]
    private static partial Regex IdInName();
}
