using AcPhys.Contract;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// verify --impl-cmd, end to end: the reference served over protocol v1 and the Python example pass with no false
/// alarm; their seeded bugs are caught through the protocol with a shrunk case; broken children are exit 2.
/// </summary>
public sealed class OutOfProcessTests
{
    [Fact]
    public void ServedReferencePassesEveryTestedInvariant()
    {
        // The whole catalogue over the process boundary: the wire encoding loses nothing the invariants see.
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand, "--cases", "150", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains(" 0 failed", run.Out, StringComparison.Ordinal);
        Assert.Contains("NOT TESTED HYSTERESIS", run.Out, StringComparison.Ordinal); // serve declares the retail pick
        Assert.Contains(Expected.CleanSummary(ReferenceAdapter.Instance.Ops), run.Out, StringComparison.Ordinal); // scenes travel too
        Assert.DoesNotMatch(new System.Text.RegularExpressions.Regex("lacks *$", System.Text.RegularExpressions.RegexOptions.Multiline), run.Out); // Op.All is every op (issue 25)
    }

    [Fact]
    public void ScenesTravelWholeToAServerWithoutLoadScene()
    {
        // Compatibility: a server that does not announce load_scene is sent the scene in every find_cell, as before.
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --no-load-scene", "--only", "INTERIOR-WINS,FIND-CELL-CONFORMANCE", "--cases", "100", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("verify: 2 invariants, 2 passed, 0 failed, 0 not tested", run.Out, StringComparison.Ordinal);
        Assert.DoesNotContain("load_scene", run.Out, StringComparison.Ordinal);
    }

    [Fact]
    public void ServedIndoorFaultIsCaughtThroughScenesOnTheWire()
    {
        // outdoor-wins (the pick prefers the land cell) is only visible with a scene: it must cross the protocol.
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault outdoor-wins", "--only", "INTERIOR-WINS", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("FAIL INTERIOR-WINS on reference+outdoor-wins", run.Out, StringComparison.Ordinal);
        Assert.Matches(@"  shrunk     (cottage|estate-\w+)-1 ", run.Out); // shrunk to a one-room scene (which kind depends on the case stream)
    }

    [Fact]
    public void ServedPlantedFaultIsCaughtWithShrunkWalkAndReplayLine()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault clamp-106", "--only", "NO-BOUNDARY-FREEZE", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("FAIL NO-BOUNDARY-FREEZE on reference+clamp-106", run.Out, StringComparison.Ordinal);
        string replay = Line(run.Out, "  replay     acphys verify");
        Assert.Contains("--impl-cmd", replay, StringComparison.Ordinal);
        Assert.Contains("--fault clamp-106", replay, StringComparison.Ordinal);
    }

    // The Python example's outdoor half, announced alone (--ops), the outdoor parts variant included: the indoor half is
    // judged by PythonIndoorTests.
    private const string PythonOutdoorOps = "blockid_to_lcoord,gid_to_lcoord,lcoord_to_gid,inbound_valid_cellid,get_outside_lcoord,adjust_to_outside,outside_cells,outside_cells_parts,find_cell,find_cell_walk";

    [RequiresPythonFact]
    public void PythonExamplePassesWithNoFalseAlarm()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample + " --ops " + PythonOutdoorOps, "--cases", "400", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("against python-example;", run.Out, StringComparison.Ordinal);
        Assert.Contains(Expected.CleanSummary(Op.OpenLand), run.Out, StringComparison.Ordinal);
        Assert.Contains("; lacks find_cell_scene", run.Out, StringComparison.Ordinal);
        Assert.Contains("NOT TESTED INTERIOR-WINS: implementation lacks find_cell_scene", run.Out, StringComparison.Ordinal);
        Assert.Contains("[impl] acphys_impl.py: protocol 1", run.Err, StringComparison.Ordinal); // its stderr log is passed through
    }

    [RequiresPythonFact(DisplayName = "PY-PARTS: the Python example answers outside_cells_parts (acphys_parts.py, facts §3.4): PARTS-COVERAGE and PARTS-SOUNDNESS are judged and pass")]
    public void PythonExamplePassesTheOutdoorPartsInvariants()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample, "--only", "PARTS-COVERAGE,PARTS-SOUNDNESS", "--cases", "400", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("verify: 2 invariants, 2 passed, 0 failed, 0 not tested", run.Out, StringComparison.Ordinal);
    }

    [RequiresPythonFact]
    public void PythonExampleAnswersEveryPipelinedQueryAsTheReference()
    {
        // Its land test rounds as retail's float32 point_in_poly2D (facts §5.5), so every streamed answer equals the
        // reference's guess and no run is repeated (with a plain closed-square test, 2 of 42 runs were repeated at
        // 400 cases: a centre 1e-7 m west of a cell edge, inside by float32 rounding).
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample + " --ops " + PythonOutdoorOps + ",pipeline", "--cases", "400", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("invariant runs streamed, 0 replayed from the first differing answer", run.Err, StringComparison.Ordinal);
    }

    [RequiresPythonFact]
    public void PythonClampBugIsCaughtThroughTheProtocolWithAShrunkWalk()
    {
        var run = Acphys.Run(
            ["verify", "--impl-cmd", Acphys.PythonExample, "--only", "NO-BOUNDARY-FREEZE", "--cases", "500", "--timeout", "60"],
            new Dictionary<string, string> { ["ACPHYS_PY_BUG"] = "clamp-106" });
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("FAIL NO-BOUNDARY-FREEZE on python-example+clamp-106", run.Out, StringComparison.Ordinal);

        // Shrunk to a walk of at most two steps (one step over a block line freezes the clamped port).
        string shrunk = Line(run.Out, "  shrunk     start ");
        string steps = shrunk[(shrunk.IndexOf("steps [", StringComparison.Ordinal) + 7)..].TrimEnd(']');
        Assert.True(steps.Split(';').Length <= 2, shrunk);
        Assert.Contains("containing 0x00000000", run.Out, StringComparison.Ordinal);
        string caseFile = Line(run.Out, "  case file  ")["  case file  ".Length..].Trim();
        Assert.True(File.Exists(Path.IsPathRooted(caseFile) ? caseFile : Path.Combine(RepoPaths.Root, caseFile)), caseFile);
    }

    [RequiresPythonFact]
    public void PythonTruncationBugIsCaughtWithAShrunkCase()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample + " --bug trunc-floor", "--only", "ADJUST-RANGE,OUTSIDE-LCOORD-GEOMETRY", "--cases", "500", "--timeout", "60"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("FAIL ADJUST-RANGE on python-example+trunc-floor", run.Out, StringComparison.Ordinal);
        Assert.Contains("FAIL OUTSIDE-LCOORD-GEOMETRY on python-example+trunc-floor", run.Out, StringComparison.Ordinal);
        Assert.Contains("  shrunk     cell=", run.Out, StringComparison.Ordinal);
    }

    [RequiresPythonFact]
    public void PartialImplementationIsTestedOnWhatItHasAndTheRestIsListed()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample + " --ops lcoord_to_gid,gid_to_lcoord", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains(Expected.CleanSummary(Op.LcoordToGid | Op.GidToLcoord), run.Out, StringComparison.Ordinal);
        Assert.Contains("capabilities: offers gid_to_lcoord, lcoord_to_gid; lacks blockid_to_lcoord, inbound_valid_cellid,", run.Out, StringComparison.Ordinal);
        Assert.Contains("NOT TESTED COVERAGE: implementation lacks outside_cells", run.Out, StringComparison.Ordinal);
        Assert.Contains("NOT TESTED ADJUST-RANGE: implementation lacks adjust_to_outside", run.Out, StringComparison.Ordinal);
    }

    [Fact]
    public void HangingImplementationIsReportedWithinTheTimeout()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.Script("hang-after-hello.sh"), "--timeout", "1", "--only", "LCOORD-ROUNDTRIP"]);
        Assert.True(run.Exit == 2, run.ToString());
        // Which land op comes first depends on the pr case stream (issue 40's low-word bounds made it lcoord_to_gid).
        Assert.Matches(@"did not answer '(gid_to_lcoord|lcoord_to_gid)' within 1 s \(--timeout\); it was killed", run.Err);
        Assert.Contains("hang-after-hello: going to sleep", run.Err, StringComparison.Ordinal); // its last stderr lines are quoted
        Assert.True(run.Elapsed < TimeSpan.FromSeconds(20), run.ToString());
    }

    [Fact]
    public void CrashingImplementationIsExit2WithItsExitCodeAndLog()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.Script("crash-after-hello.sh"), "--only", "LCOORD-ROUNDTRIP", "--quiet"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("acphys verify: the implementation could not answer:", run.Err, StringComparison.Ordinal);
        Assert.Contains("exited with code 3", run.Err, StringComparison.Ordinal);
        Assert.Contains("simulated segmentation fault", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", run.Err, StringComparison.Ordinal); // no stack trace
    }

    [Fact]
    public void GarbageHandshakeIsExit2WithClearMessage()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.Script("garbage.sh"), "--timeout", "5"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("answered 'hello' with something that is not protocol v1", run.Err, StringComparison.Ordinal);
        Assert.Contains("Welcome to my physics server", run.Err, StringComparison.Ordinal);
    }

    [Fact]
    public void GarbageAnswerIsExit2NotAViolation()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.Script("garbage-answer.sh"), "--only", "LCOORD-ROUNDTRIP", "--timeout", "60"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Matches(@"answered '(gid_to_lcoord|lcoord_to_gid)' with something that is not protocol v1: ", run.Err);
        Assert.Contains("Answer: {\"cell\":12345}", run.Err, StringComparison.Ordinal); // the garbage is quoted
    }

    [Fact]
    public void MissingCommandIsExit2()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", "/nonexistent/impl --serve", "--only", "LCOORD-ROUNDTRIP"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("could not answer", run.Err, StringComparison.Ordinal);
    }

    private static string Line(string text, string prefix) =>
        text.Split('\n').FirstOrDefault(l => l.StartsWith(prefix, StringComparison.Ordinal)) ?? throw new Xunit.Sdk.XunitException($"no line starting '{prefix}' in:\n{text}");
}
