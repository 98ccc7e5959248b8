using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// <c>acphys fuzz --impl / --impl-cmd</c> (issue 40): a port's crash inputs are triaged by the gate's oracle into the
/// port's regression folder, each with a replay line naming the port that exits 1 on the port and 0 on the reference;
/// a child that crashes is a finding of its own kind and is restarted; targets a port cannot be fuzzed on are refused.
/// These run triage alone (<c>--triage-only</c>: no afl-fuzz, no build), on crash inputs an afl-fuzz campaign wrote;
/// the campaigns themselves are <c>fuzz/tests/port.sh</c> (nightly, measured in docs/fuzzing.md).
/// </summary>
public sealed class FuzzPortTests : IDisposable
{
    // Crash inputs from campaigns on this machine (the seed field of the regressions they became).
    private const string MapEdgeInput = "00ffffff1701"; // land: a cell in block row 0xFF, which inbound-x-only accepts
    private const string HangInput = "0001ac2b4a"; // land: mode 0, cell 0x4A2BAC01 (the example port's hang bug), the rest zero
    private const string TruncFloorInput = "00ffdd00000800409fffffff01fffffff51100000000409fffffff0101006f"; // land: x just below 0

    private readonly string work = Path.Combine(Path.GetTempPath(), "acphys-fuzz-port-" + Guid.NewGuid().ToString("N"));

    private static string ExampleAdapter
    {
        get
        {
            string configuration = AppContext.BaseDirectory.Contains("/Debug/", StringComparison.Ordinal) ? "Debug" : "Release";
            return Path.Combine(RepoPaths.Root, "examples", "dotnet-adapter", "bin", configuration, "net10.0", "ExampleAdapter.dll");
        }
    }

    private string Regressions => Path.Combine(work, "regressions");

    [Fact(DisplayName = "fuzz --impl: a crash input of the seeded bug becomes a MAP-EDGE regression in the port's folder; its replay line names the port, exits 1 on it, 0 on the reference and 0 on the clean port")]
    public void ImplFindingReplaysOnThePortOnly()
    {
        var bug = new Dictionary<string, string> { ["ACPHYS_EXAMPLE_BUG"] = "inbound-x-only" };
        var run = Triage(["--target", "land", "--impl", ExampleAdapter], MapEdgeInput, bug);
        Assert.True(run.Exit == 1, run.ToString());
        string file = Assert.Single(Directory.GetFiles(Regressions, "MAP-EDGE-*.json"));
        Assert.Contains($"replay {file} --impl {ExampleAdapter}", run.Out, StringComparison.Ordinal);
        Assert.Contains("invariants tested (the rest not tested, as in the gate): LCOORD-ROUNDTRIP", run.Out, StringComparison.Ordinal);

        Assert.Equal(1, Acphys.Run(["replay", file, "--impl", ExampleAdapter], bug).Exit);
        Assert.Equal(0, Acphys.Run(["replay", file]).Exit);
        Assert.Equal(0, Acphys.Run(["replay", file, "--impl", ExampleAdapter]).Exit);
    }

    [RequiresPythonFact(DisplayName = "fuzz --impl-cmd: a crash input of the Python example's trunc-floor becomes an OUTSIDE-LCOORD-GEOMETRY regression whose --impl-cmd replay exits 1 on the port and 0 on the reference")]
    public void ImplCmdFindingReplaysOnThePortOnly()
    {
        string port = Acphys.PythonExample + " --bug trunc-floor";
        var run = Triage(["--target", "land", "--impl-cmd", port], TruncFloorInput);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("coverage: the harness side's", run.Out, StringComparison.Ordinal);
        var files = Directory.GetFiles(Regressions, "*.json");
        Assert.Contains(files, f => Path.GetFileName(f).StartsWith("OUTSIDE-LCOORD-GEOMETRY-", StringComparison.Ordinal));
        foreach (string file in files) // the crash input's and those of the seeds that already fail
        {
            Assert.Contains($"replay {file} --impl-cmd '{port}'", run.Out, StringComparison.Ordinal);
            Assert.Equal(1, Acphys.Run(["replay", file, "--impl-cmd", port]).Exit);
            Assert.Equal(0, Acphys.Run(["replay", file]).Exit);
            Assert.Equal(0, Acphys.Run(["replay", file, "--impl-cmd", Acphys.PythonExample]).Exit);
        }
    }

    [RequiresPythonFact(DisplayName = "fuzz --impl-cmd: a child that crashes on an input is an ADAPTER-FAILURE finding kept raw in REGRESSIONS/crashes, and the next input gets a new child")]
    public void CrashingChildIsAFindingAndIsRestarted()
    {
        string port = $"python3 {Path.Combine(RepoPaths.Root, "e2e", "Impls", "crash-on-cell.py")} 0x..FF {Acphys.PythonExample}";
        string crashes = Path.Combine(work, "campaign", "sync", "main", "crashes");
        Directory.CreateDirectory(crashes);
        File.WriteAllBytes(Path.Combine(crashes, "id:000001,sig:06,src:000000,time:1,execs:1,op:havoc,rep:1"), Convert.FromHexString(TruncFloorInput));
        var run = Triage(["--target", "land", "--impl-cmd", port], MapEdgeInput);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("- ADAPTER-FAILURE x", run.Out, StringComparison.Ordinal);
        Assert.Single(Directory.GetFiles(Path.Combine(Regressions, "crashes"), "land-ADAPTER-FAILURE-*.bin"));

        // The other input is the Python example's clean answer after the crash: a new child answered it (it passes).
        Assert.Contains("(does not reproduce) x1", run.Out, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "fuzz --impl: a target none of whose invariants the port is testable for, a parser target, and --fault with a port are refused with exit 2 and a reason")]
    public void UnfuzzableChoicesAreRefused()
    {
        var walk = Acphys.Run(["fuzz", "--target", "walk", "--impl", ExampleAdapter, "--campaign", Path.Combine(work, "c1"), "--quiet"]);
        Assert.True(walk.Exit == 2, walk.ToString());
        Assert.Contains("target walk: none of its", walk.Err, StringComparison.Ordinal);
        Assert.Contains("(it offers blockid_to_lcoord, gid_to_lcoord", walk.Err, StringComparison.Ordinal);

        var parser = Acphys.Run(["fuzz", "--target", "corpus", "--impl", ExampleAdapter, "--campaign", Path.Combine(work, "c2"), "--quiet"]);
        Assert.True(parser.Exit == 2, parser.ToString());
        Assert.Contains("fuzzes the suite's own readers", parser.Err, StringComparison.Ordinal);

        var fault = Acphys.Run(["fuzz", "--target", "land", "--fault", "trunc-floor", "--impl", ExampleAdapter, "--campaign", Path.Combine(work, "c3"), "--quiet"]);
        Assert.True(fault.Exit == 2, fault.ToString());
        Assert.Contains("--fault configures the bundled reference", fault.Err, StringComparison.Ordinal);
    }

    public void Dispose()
    {
        if (Directory.Exists(work))
        {
            Directory.Delete(work, recursive: true);
        }
    }

    [Fact(DisplayName = "fuzz --impl: an input that hangs the in-process port (afl's hangs/) is a HANG finding in the port's hangs/ folder; its replay line names the port and exits 2 on it (the watchdog), 0 on the reference and on the clean port")]
    public void ImplHangIsAFindingOfItsOwnKind()
    {
        var bug = new Dictionary<string, string> { ["ACPHYS_PORT_BUG"] = "hang" };
        string hangs = Path.Combine(work, "campaign", "sync", "main", "hangs");
        Directory.CreateDirectory(hangs);
        File.WriteAllBytes(Path.Combine(hangs, "id:000000,src:000000,time:1,execs:1,op:havoc,rep:1"), Convert.FromHexString(HangInput));
        var run = Acphys.Run(["fuzz", "--target", "land", "--impl", GateTestRun.ExamplePortDll, "--triage-only", "--campaign", Path.Combine(work, "campaign"), "--regressions", Regressions, "--quiet"], bug);
        Assert.True(run.Exit == 1, run.ToString());
        string file = Assert.Single(Directory.GetFiles(Path.Combine(Regressions, "hangs"), "land-HANG-*.json"));
        Assert.Contains("HANG", run.Out, StringComparison.Ordinal);
        Assert.Contains($"replay: acphys replay {file} --impl {GateTestRun.ExamplePortDll}", run.Out, StringComparison.Ordinal);

        var replay = Acphys.Run(["replay", file, "--impl", GateTestRun.ExamplePortDll], bug); // the printed line
        Assert.True(replay.Exit == 2, replay.ToString());
        Assert.Contains("did not return from", replay.Err, StringComparison.Ordinal);
        Assert.Equal(0, Acphys.Run(["replay", file]).Exit);
        Assert.Equal(0, Acphys.Run(["replay", file, "--impl", GateTestRun.ExamplePortDll]).Exit);
    }

    // One crash file where afl-fuzz writes them, then triage alone.
    private Run Triage(IEnumerable<string> choice, string hex, IReadOnlyDictionary<string, string>? environment = null)
    {
        string crashes = Path.Combine(work, "campaign", "sync", "main", "crashes");
        Directory.CreateDirectory(crashes);
        File.WriteAllBytes(Path.Combine(crashes, "id:000000,sig:06,src:000000,time:1,execs:1,op:havoc,rep:1"), Convert.FromHexString(hex));
        return Acphys.Run(["fuzz", .. choice, "--triage-only", "--campaign", Path.Combine(work, "campaign"), "--regressions", Regressions, "--quiet"], environment);
    }
}
