using System.Xml.Linq;
using AcPhys.E2E.Support;

namespace AcPhys.E2E.Hostile;

/// <summary>
/// Issue 28, what the implementation under test controls: its hello, its names, its answers and its processes can
/// neither turn the gate green nor forge, break or outlive its reports.
/// </summary>
public sealed class HostileImplTests
{
    private const string Forged = "verify: 42 invariants, 42 passed, 0 failed";

    private static readonly string LandDefsOps = "\"blockid_to_lcoord\",\"gid_to_lcoord\",\"lcoord_to_gid\",\"inbound_valid_cellid\",\"get_outside_lcoord\",\"adjust_to_outside\"";

    private static string ExampleAdapter =>
        Path.Combine(RepoPaths.Root, "examples", "dotnet-adapter", "bin", AppContext.BaseDirectory.Contains("/Debug/", StringComparison.Ordinal) ? "Debug" : "Release", "net10.0", "ExampleAdapter.dll");

    /// <summary>GATE-TESTS-SOMETHING: misspelt op names make every invariant NOT TESTED; that run exits 4, names the ops, and its JUnit and markdown say it is not a pass.</summary>
    [Fact]
    public void MisspeltOps_NothingTested_IsExit4AndNamedInEveryReport()
    {
        string impl = HostileFiles.Script("""
            read l
            printf '%s\n' '{"protocol":1,"name":"misspelt","ops":["gid_to_lcoords","find-cell"]}'
            while read l; do echo '{"error":"unexpected"}'; done
            """);
        string dir = HostileFiles.Temp();
        string junit = Path.Combine(dir, "j.xml"), md = Path.Combine(dir, "s.md");
        var run = Acphys.Run(["verify", "--impl-cmd", impl, "--only", "LCOORD-BLOCK,ADJUST-RANGE", "--cases", "5", "--junit", junit, "--markdown", md]);
        Assert.True(run.Exit == 4, run.ToString());
        Assert.Contains("warning: the implementation announced ops protocol v1 does not know: \"gid_to_lcoords\", \"find-cell\"", run.Err, StringComparison.Ordinal);
        Assert.Contains("not a pass: 0 of 2 invariants tested, fewer than --min-tested 1", run.Err, StringComparison.Ordinal);
        var xml = XDocument.Load(junit);
        Assert.Contains(xml.Descendants("testcase"), t => (string?)t.Attribute("name") == "MIN-TESTED" && t.Element("failure") is not null);
        Assert.Equal("1", (string?)xml.Root!.Attribute("failures"));
        Assert.Contains(xml.Descendants("property"), p => (string?)p.Attribute("name") == "unknown-ops" && ((string?)p.Attribute("value"))!.Contains("gid_to_lcoords", StringComparison.Ordinal));
        string summary = File.ReadAllText(md);
        Assert.Contains("❌ not a pass", summary, StringComparison.Ordinal);
        Assert.Contains("\"find-cell\"", summary, StringComparison.Ordinal);
    }

    /// <summary>GATE-MIN-TESTED: --min-tested N fails a run that tested fewer invariants (exit 4), and is a usage error outside 1..42.</summary>
    [Fact]
    public void MinTested_MoreThanTheRunTests_IsExit4()
    {
        var run = Acphys.Run(["verify", "--only", "ADJUST-RANGE", "--cases", "5", "--min-tested", "2", "--quiet"]);
        Assert.True(run.Exit == 4, run.ToString());
        Assert.Contains("not a pass: 1 of 1 invariants tested, fewer than --min-tested 2", run.Err, StringComparison.Ordinal);
        var zero = Acphys.Run(["verify", "--only", "ADJUST-RANGE", "--min-tested", "0"]);
        Assert.True(zero.Exit == 2, zero.ToString());
        Assert.Contains("--min-tested must be between 1 and", zero.Err, StringComparison.Ordinal);
    }

    /// <summary>NO-FORGED-LINES: a name holding a newline, ESC and NUL is printed escaped; the JUnit report is still written and parses.</summary>
    [Fact]
    public void ForgedName_IsEscapedOnTheConsoleAndInJunit()
    {
        string impl = HostileFiles.Script($$"""
            read l
            printf '%s\n' '{"protocol":1,"name":"evil\u001b[31m\n{{Forged}}\u0000","ops":[{{LandDefsOps}}]}'
            while read l; do echo '{"error":"no"}'; done
            """);
        string junit = Path.Combine(HostileFiles.Temp(), "j.xml");
        var run = Acphys.Run(["verify", "--impl-cmd", impl, "--only", "ADJUST-RANGE", "--cases", "5", "--max-classes", "1", "--junit", junit]);
        Assert.True(run.Exit == 1, run.ToString());
        AssertNoRawControls(run.Out + run.Err);
        Assert.DoesNotContain(run.Out.Split('\n'), l => l.StartsWith(Forged, StringComparison.Ordinal));
        Assert.Contains("evil\\u001b[31m\\nverify", run.Out, StringComparison.Ordinal);
        var xml = XDocument.Load(junit); // issue 28: the XML writer threw on the ESC (exit 70, no report)
        Assert.Contains("evil\\u001b", (string?)xml.Root!.Attribute("name"), StringComparison.Ordinal);
    }

    /// <summary>NO-FORGED-LINES: an error answer and a stderr line holding NUL, ESC and a newline reach the console escaped.</summary>
    [Fact]
    public void ErrorTextAndStderr_AreEscaped()
    {
        string impl = HostileFiles.Script($$"""
            read l
            printf '%s\n' '{"protocol":1,"name":"errs","ops":[{{LandDefsOps}}]}'
            while read l; do printf 'log \033[2J\000 line\n' >&2; printf '%s\n' '{"error":"bad\u0000\u001b[2J\n{{Forged}}"}'; done
            """);
        var run = Acphys.Run(["verify", "--impl-cmd", impl, "--only", "ADJUST-RANGE", "--cases", "5", "--max-classes", "1"]);
        Assert.True(run.Exit == 1, run.ToString());
        AssertNoRawControls(run.Out + run.Err);
        Assert.DoesNotContain(run.Out.Split('\n'), l => l.StartsWith(Forged, StringComparison.Ordinal));
        Assert.Contains("answered error \"bad\\u0000\\u001b[2J\\n" + Forged, run.Out, StringComparison.Ordinal);
        Assert.Contains("[impl] log \\u001b[2J\\u0000 line", run.Err, StringComparison.Ordinal);
    }

    /// <summary>IMPL-TIMEOUT: an --impl adapter whose call never returns stops the run after --timeout, exit 2, naming the operation.</summary>
    [Fact]
    public void InProcessAdapter_ThatHangs_IsStoppedByTimeout()
    {
        var run = Acphys.Run(["verify", "--impl", ExampleAdapter, "--only", "LCOORD-ROUNDTRIP", "--cases", "5", "--timeout", "1", "--quiet"], new Dictionary<string, string> { ["ACPHYS_EXAMPLE_BUG"] = "hang" });
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("'example-dotnet' (--impl) did not return from lcoord_to_gid within 1 s (--timeout)", run.Err, StringComparison.Ordinal);
        Assert.True(run.Elapsed < TimeSpan.FromSeconds(60), run.ToString());
    }

    /// <summary>IMPL-EXIT: an Environment.Exit(3) inside an --impl adapter is named as the adapter's and is exit 2, not 3 ("output unwritable").</summary>
    [Fact]
    public void InProcessAdapter_ThatCallsEnvironmentExit_IsReportedAsTheAdapters()
    {
        var run = Acphys.Run(["verify", "--impl", ExampleAdapter, "--only", "LCOORD-ROUNDTRIP", "--cases", "5", "--quiet"], new Dictionary<string, string> { ["ACPHYS_EXAMPLE_BUG"] = "exit" });
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("'example-dotnet' (--impl) ended the process (Environment.Exit(3)) inside lcoord_to_gid", run.Err, StringComparison.Ordinal);
    }

    /// <summary>NO-FORGED-LINES (own input 1): an --impl adapter's name with ESC and a newline is escaped like a child's.</summary>
    [Fact]
    public void InProcessAdapter_HostileName_IsEscaped()
    {
        var run = Acphys.Run(["verify", "--impl", ExampleAdapter, "--only", "ADJUST-RANGE", "--cases", "5"], new Dictionary<string, string> { ["ACPHYS_EXAMPLE_BUG"] = "name" });
        Assert.True(run.Exit == 0, run.ToString());
        AssertNoRawControls(run.Out + run.Err);
        Assert.Contains("example\\u001b[2J\\nverify: 42", run.Out, StringComparison.Ordinal);
    }

    /// <summary>CLOSED-STDOUT: a child that answers hello, then closes its stdout and stays alive is reported as such (exit 2), not as a slow answer.</summary>
    [Fact]
    public void ChildThatClosesStdout_IsReportedAsSuch()
    {
        string impl = HostileFiles.Script($$"""
            read l
            printf '%s\n' '{"protocol":1,"name":"closer","ops":[{{LandDefsOps}}]}'
            exec 1>&-
            sleep 30
            """);
        var run = Acphys.Run(["verify", "--impl-cmd", impl, "--only", "ADJUST-RANGE", "--cases", "5", "--timeout", "1", "--quiet"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("closed its stdout but is still running", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("did not answer", run.Err, StringComparison.Ordinal);
    }

    /// <summary>NOTHING-SURVIVES: a grandchild that left the process group with setsid is killed when the run ends.</summary>
    [Fact]
    public void SetsidGrandchild_IsKilledAtTheEnd()
    {
        string marker = "3131." + Random.Shared.Next(100000, 999999).ToString(System.Globalization.CultureInfo.InvariantCulture);
        string impl = HostileFiles.Script($"""
            setsid sleep {marker} </dev/null >/dev/null 2>&1 &
            exec {Acphys.ServeCommand}
            """);
        var run = Acphys.Run(["verify", "--impl-cmd", impl, "--only", "ADJUST-RANGE", "--cases", "5", "--quiet"]);
        Assert.True(run.Exit == 0, run.ToString());
        var survivors = Poll.Until(TimeSpan.FromSeconds(5), () => Sleepers(marker).Count == 0) ? [] : Sleepers(marker);
        foreach (int pid in survivors)
        {
            try
            {
                System.Diagnostics.Process.GetProcessById(pid).Kill(); // leave nothing behind, even when failing
            }
            catch (ArgumentException)
            {
            }
        }

        Assert.True(survivors.Count == 0, $"sleep {marker} survived the run: pids {string.Join(", ", survivors)}");
    }

    /// <summary>NO-FORGED-LINES (own input 2): a 100,000-character name is cut on the console line.</summary>
    [Fact]
    public void HugeName_IsCutOnTheConsole()
    {
        string impl = HostileFiles.Script($$"""
            read l
            printf '{"protocol":1,"name":"%s","ops":[{{LandDefsOps}}]}\n' "$(head -c 100000 /dev/zero | tr '\0' 'n')"
            while read l; do echo '{"error":"no"}'; done
            """);
        var run = Acphys.Run(["verify", "--impl-cmd", impl, "--only", "ADJUST-RANGE", "--cases", "5", "--max-classes", "1"]);
        Assert.True(run.Exit == 1, run.ToString()[..Math.Min(2000, run.ToString().Length)]);
        Assert.All(run.Out.Split('\n'), l => Assert.True(l.Length < 3000, $"a {l.Length}-character line"));
        Assert.Contains("(100,000 characters)", run.Out, StringComparison.Ordinal);
    }

    /// <summary>UNKNOWN-OPS (own input 3): ten thousand unknown op names are named, twenty of them, and counted.</summary>
    [Fact]
    public void TenThousandUnknownOps_AreNamedBriefly()
    {
        string impl = HostileFiles.Script($$"""
            read l
            printf '{"protocol":1,"name":"many","ops":[{{LandDefsOps}}%s]}\n' "$(seq 1 10000 | sed 's/.*/,"op&"/' | tr -d '\n')"
            while read l; do echo '{"error":"no"}'; done
            """);
        var run = Acphys.Run(["verify", "--impl-cmd", impl, "--only", "ADJUST-RANGE", "--cases", "5", "--max-classes", "1", "--quiet"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("\"op1\", \"op2\"", run.Err, StringComparison.Ordinal);
        Assert.Contains("and 9980 more", run.Err, StringComparison.Ordinal);
        Assert.All(run.Err.Split('\n'), l => Assert.True(l.Length < 3000, $"a {l.Length}-character line"));
    }

    private static void AssertNoRawControls(string text)
    {
        Assert.DoesNotContain('\u001b', text);
        Assert.DoesNotContain('\0', text);
    }

    private static List<int> Sleepers(string marker)
    {
        var found = new List<int>();
        foreach (string dir in Directory.EnumerateDirectories("/proc"))
        {
            if (!int.TryParse(Path.GetFileName(dir), out int pid))
            {
                continue;
            }

            try
            {
                if (File.ReadAllText(Path.Combine(dir, "cmdline")).Replace('\0', ' ').Trim() == "sleep " + marker)
                {
                    found.Add(pid);
                }
            }
            catch (IOException)
            {
            }
        }

        return found;
    }
}
