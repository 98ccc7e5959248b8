using System.Text.RegularExpressions;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// The nightly fuzzing workflow docs/ports.md gives a port's repository (section 14) does what it says on the examples:
/// its <c>Build</c>, <c>Fuzz</c> and <c>Replay</c> commands, read from the document's YAML, run with a short
/// <c>FUZZ_MINUTES</c> on examples/dotnet-port in process (<c>PORT_DLL</c>) and on the Python example over protocol
/// (<c>PORT_CMD</c>): a seeded bug's night writes regressions that replay with exit 1 on the port and 0 on the
/// reference, a clean night resumes the queue and writes nothing.
/// </summary>
[Collection(PortGateCollection.Name)]
public sealed partial class PortNightlyTests : IDisposable
{
    private readonly string work = Directory.CreateTempSubdirectory("acphys-e2e-nightly-").FullName;

    public void Dispose() => Directory.Delete(work, recursive: true);

    [RequiresAflFact(DisplayName = "PORT-NIGHTLY: the documented nightly workflow's commands find the .NET example port's seeded bug in process, and a clean night resumes the queue with no finding")]
    public void DotnetPortInProcess()
    {
        var environment = Environment("land", dll: Path.Combine(RepoPaths.Root, "examples", "dotnet-port", "bin", GateTestRun.Configuration, "net10.0", "ExamplePort.dll"), cmd: string.Empty);
        environment["PORT_PROJECT"] = Path.Combine(RepoPaths.Root, "examples", "dotnet-port", "ExamplePort.csproj");
        var steps = WorkflowSteps();
        var build = Bash(steps["Build"], environment);
        Assert.True(build.Exit == 0, build.ToString());

        environment["ACPHYS_PORT_BUG"] = "inbound-x-only";
        var files = Night(steps, environment, expectFinding: true);
        environment.Remove("ACPHYS_PORT_BUG");
        foreach (string file in files)
        {
            Assert.Equal(0, Acphys.Run(["replay", file]).Exit); // the reference passes it
            Assert.Equal(0, Acphys.Run(["replay", file, "--impl", environment["PORT_DLL"]]).Exit); // so does the clean port
        }

        var clean = Night(steps, environment, expectFinding: false, resumes: true);
        Assert.Empty(clean);
    }

    [RequiresAflFact(DisplayName = "PORT-NIGHTLY: the documented nightly workflow's commands find the Python example's seeded bug over protocol v1 (PORT_CMD)")]
    public void PythonPortOverProtocol()
    {
        var environment = Environment("land", dll: string.Empty, cmd: Acphys.PythonExample + " --bug trunc-floor");
        environment["PORT_PROJECT"] = string.Empty;
        var steps = WorkflowSteps();
        Assert.Equal(0, Bash(steps["Build"], environment).Exit); // nothing to build
        foreach (string file in Night(steps, environment, expectFinding: true))
        {
            Assert.Equal(0, Acphys.Run(["replay", file]).Exit);
            Assert.Equal(0, Acphys.Run(["replay", file, "--impl-cmd", Acphys.PythonExample]).Exit);
        }
    }

    // One night: the Fuzz step (its exit recorded in GITHUB_ENV as the workflow reads it), then the Replay step.
    private List<string> Night(Dictionary<string, string> steps, Dictionary<string, string> environment, bool expectFinding, bool resumes = false)
    {
        string githubEnv = Path.Combine(work, "github.env");
        File.WriteAllText(githubEnv, string.Empty);
        string queue = Path.Combine(environment["CAMPAIGN"], "sync", "main", "queue");
        var before = resumes ? Directory.GetFiles(queue).ToDictionary(f => f, File.GetLastWriteTimeUtc) : [];
        var fuzz = Bash(steps["Fuzz"], environment);
        Assert.True(fuzz.Exit == 0, fuzz.ToString()); // 0 and 1 let the job go on to upload and propose
        Assert.Equal($"FUZZ_EXIT={(expectFinding ? 1 : 0)}", File.ReadAllText(githubEnv).Trim());
        Assert.True(File.Exists(Path.Combine(environment["CAMPAIGN"], "summary.txt")), fuzz.ToString());
        if (resumes)
        {
            // The cached queue is resumed, not wiped: afl-fuzz says so, and the queue holds at least last night's entries.
            Assert.NotEmpty(before);
            string log = File.ReadAllText(Path.Combine(environment["CAMPAIGN"], "logs", "afl-main.log"));
            Assert.Contains("Resuming", log, StringComparison.Ordinal);
            Assert.True(Directory.GetFiles(queue).Length >= before.Count, $"{Directory.GetFiles(queue).Length} queue entries after the resumed night, {before.Count} before");
        }

        var files = Directory.Exists(environment["REGRESSIONS"])
            ? Directory.GetFiles(environment["REGRESSIONS"], "*.json").Where(f => File.GetLastWriteTimeUtc(f) >= File.GetLastWriteTimeUtc(Path.Combine(work, ".acphys", "night-start"))).ToList()
            : [];
        Assert.Equal(expectFinding, files.Count > 0);
        foreach (string file in files)
        {
            Assert.Contains("replay: acphys replay " + file, fuzz.Out, StringComparison.Ordinal); // the printed line names the file
        }

        var replay = Bash(steps["Replay"], environment);
        Assert.True(replay.Exit == 0, replay.ToString()); // every new file exits 1 on the port
        return files;
    }

    private Dictionary<string, string> Environment(string target, string dll, string cmd)
    {
        string wrapper = Path.Combine(work, "acphys");
        File.WriteAllText(wrapper, $"#!/bin/sh\nexec dotnet '{Acphys.Dll}' \"$@\"\n");
        if (!OperatingSystem.IsWindows()) // the workflow runs bash on Linux; afl-fuzz has no Windows build
        {
            File.SetUnixFileMode(wrapper, UnixFileMode.UserRead | UnixFileMode.UserWrite | UnixFileMode.UserExecute);
        }

        return new Dictionary<string, string>
        {
            ["ACPHYS"] = wrapper,
            ["PORT_DLL"] = dll,
            ["PORT_CMD"] = cmd,
            ["TARGET"] = target,
            ["FUZZ_MINUTES"] = "0.1",
            ["CAMPAIGN"] = Path.Combine(work, "campaigns", target),
            ["REGRESSIONS"] = Path.Combine(work, "regressions"),
            ["GITHUB_ENV"] = Path.Combine(work, "github.env"),
        };
    }

    private Run Bash(string command, IReadOnlyDictionary<string, string> environment) =>
        GateTestRun.Dotnet(["bash", "-eo", "pipefail", "-c", command], trx: null, environment, work, viaDotnet: false).Run;

    // The run lines of the named steps of the YAML block in docs/ports.md, section 14.
    private static Dictionary<string, string> WorkflowSteps()
    {
        string doc = File.ReadAllText(Path.Combine(RepoPaths.Root, "docs", "ports.md")).ReplaceLineEndings("\n");
        int section = doc.IndexOf("\n## 14. ", StringComparison.Ordinal);
        Assert.True(section > 0, "docs/ports.md has no section 14");
        int start = doc.IndexOf("```yaml\n", section, StringComparison.Ordinal);
        int end = doc.IndexOf("\n```", start + 1, StringComparison.Ordinal);
        var steps = StepRun().Matches(doc[start..end]).ToDictionary(m => m.Groups[1].Value, m => m.Groups[2].Value.Trim());
        Assert.Equal(["Build", "Fuzz", "Replay"], steps.Keys.Order());
        return steps;
    }

    [GeneratedRegex(@"- name: (Build|Fuzz|Replay)\n\s+run: (.+)")]
    private static partial Regex StepRun();
}
