using System.Text.RegularExpressions;
using AcPhys.Contract;
using AcPhys.E2E.Support;
using AcPhys.Protocol.Client;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Server;

namespace AcPhys.E2E;

/// <summary>
/// pipeline (docs/protocol.md, "Pipelining"): a run against a child that announces it is guessed and streamed, and
/// replayed from the first answer that differs from its guess; its verdicts, shrunk cases, seeds and replay lines are
/// those of the same run waiting for each answer.
/// </summary>
public sealed partial class PipelineTests
{
    // Outdoor and scene invariants, single queries and walks; a budget that each fault below fails within.
    private static readonly string[] Budget =
        ["--only", "COVERAGE,STABLE-PICK,NO-BOUNDARY-FREEZE,FIND-CELL-QUERY-CONFORMANCE,PORTAL-TRANSIT,FIND-CELL-CONFORMANCE", "--cases", "150", "--max-classes", "1", "--timeout", "60"];

    [Fact(DisplayName = "PIPELINE-1: serve --fault F pipelined and waiting for each answer: the same verdict, shrunk case and replay seed per invariant (stateless faults)")]
    public void PlantedFaultsGiveTheSameReportPipelined()
    {
        int replayed = 0;
        foreach (string fault in new[] { "clamp-106", "sticky-pick", "checked-cast", "inverted-portal-side", "no-visibility-filter" })
        {
            var piped = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault " + fault, .. Budget]);
            var waited = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault " + fault + " --no-pipeline", .. Budget]);
            Assert.True(piped.Exit == 1 && waited.Exit == 1, $"{fault}: the fault must be caught both ways\n{piped}\n{waited}");
            Assert.Equal(Report(waited.Out), Report(piped.Out));
            replayed += Replayed(piped.Err);
            Assert.DoesNotContain("invariant runs streamed", waited.Err, StringComparison.Ordinal);
        }

        Assert.True(replayed > 0, "no run was replayed: the differing-answer path was not exercised");
    }

    [Fact(DisplayName = "PIPELINE-2: a stateful fault (no-reset) is still failed pipelined: the same invariants fail as when each answer is awaited")]
    public void StatefulFaultFailsTheSameInvariants()
    {
        var piped = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault no-reset", .. Budget]);
        var waited = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault no-reset --no-pipeline", .. Budget]);
        Assert.True(piped.Exit == 1 && waited.Exit == 1, piped + "\n" + waited);
        Assert.Equal(Verdicts(waited.Out), Verdicts(piped.Out));
    }

    [Fact(DisplayName = "PIPELINE-3: the served reference pipelined passes with every run standing as guessed (none replayed)")]
    public void ServedReferenceIsNeverReplayed()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand, "--only", "COVERAGE,NO-BOUNDARY-FREEZE,PORTAL-TRANSIT,FIND-CELL-CONFORMANCE", "--cases", "200", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("verify: pipeline: 4 invariant runs streamed, 0 replayed", run.Err, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "PIPELINE-4: a failure found pipelined shrinks, prints its seed and replay line, and the replay fails the same way")]
    public void PipelinedFailureShrinksAndReplays()
    {
        string serve = Acphys.ServeCommand + " --fault inverted-portal-side";
        var run = Acphys.Run(["verify", "--impl-cmd", serve, "--only", "PORTAL-TRANSIT", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.True(Replayed(run.Err) > 0, "the failure was not found through a replay from a differing answer\n" + run);
        string shrunk = ReplayOutput.Line(run.Out, "  shrunk     ");
        var again = Acphys.Run(["verify", "--impl-cmd", serve, "--only", "PORTAL-TRANSIT", "--seed", ReplayOutput.Seed(run.Out), "--timeout", "60"]);
        Assert.True(again.Exit == 1, again.ToString());
        Assert.Contains(shrunk.Trim(), again.Out, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "PIPELINE-5: a pipelining child that stops answering mid-stream is exit 2 within the timeout, named as a hang")]
    public void HangMidStreamIsExit2()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.Script("pipeline-hang.sh"), "--timeout", "1", "--only", "LCOORD-ROUNDTRIP"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Matches(@"did not answer '(gid_to_lcoord|lcoord_to_gid)' within 1 s \(--timeout\); it was killed", run.Err);
        Assert.DoesNotContain("   at ", run.Err, StringComparison.Ordinal);
        Assert.True(run.Elapsed < TimeSpan.FromSeconds(60), run.ToString());
    }

    [Fact(DisplayName = "PIPELINE-6: serve takes a client-chosen scene_id in load_scene when it announces pipeline, and refuses one already loaded")]
    public void ServeTakesTheClientsSceneId()
    {
        using var piped = ProcessAdapter.Start(Acphys.ServeCommand, new ProcessAdapterOptions { Timeout = TimeSpan.FromSeconds(60) });
        Assert.NotEqual(Capability.None, piped.Capabilities & Capability.Pipeline);
        using var older = ProcessAdapter.Start(Acphys.ServeCommand + " --no-pipeline", new ProcessAdapterOptions { Timeout = TimeSpan.FromSeconds(60) });
        Assert.Equal(Capability.None, older.Capabilities & Capability.Pipeline);
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        const string Scene = """{"blocks":["0xA9B4"],"cells":[]}""";
        Assert.Equal("""{"scene_id":"mine-1"}""", server.Answer("""{"op":"load_scene","scene_id":"mine-1","scene":""" + Scene + "}"));
        Assert.Contains("already loaded", server.Answer("""{"op":"load_scene","scene_id":"mine-1","scene":""" + Scene + "}"), StringComparison.Ordinal);
        Assert.Contains("\"containing\"", server.Answer("""{"op":"find_cell","scene_id":"mine-1","cell":"0xA9B40001","spheres":[{"x":12,"y":12,"z":0.5,"r":0.5}],"current":null}"""), StringComparison.Ordinal);
        var old = new ProtocolServer(ReferenceAdapter.Instance) { Pipeline = false };
        Assert.Equal("""{"scene_id":"s1"}""", old.Answer("""{"op":"load_scene","scene_id":"mine-1","scene":""" + Scene + "}"));
    }

    // The parts variant in a scene (issue 41): a walk's parts queries are streamed like its sphere queries, one request
    // each, every one guessed by the reference; the four planted parts faults must read the same either way.
    [Fact(DisplayName = "PIPELINE-7: the parts-indoor planted faults served pipelined and waiting for each answer: the same verdict, shrunk case and replay seed per invariant")]
    public void PartsFaultsGiveTheSameReportPipelined()
    {
        int replayed = 0;
        foreach (string fault in new[] { "parts-first-part-only", "parts-box-untransformed", "parts-building-anchor-only", "parts-order-lost" })
        {
            string[] budget = ["--only", string.Join(',', AcPhys.Spec.Faults.PlantedFaults.Find(fault)!.CaughtBy), "--cases", "300", "--max-classes", "1", "--timeout", "60"];
            var piped = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault " + fault, .. budget]);
            var waited = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault " + fault + " --no-pipeline", .. budget]);
            Assert.True(piped.Exit == 1 && waited.Exit == 1, $"{fault}: the fault must be caught both ways\n{piped}\n{waited}");
            Assert.Equal(Report(waited.Out), Report(piped.Out));
            replayed += Replayed(piped.Err);
        }

        Assert.True(replayed > 0, "no parts run was replayed: the differing-answer path was not exercised");
    }

    // A port killed, or answering garbage, in the middle of a stream of parts queries: the 40th request line is a parts
    // query of the first walk (hello, load_scene, then the walk's queries, streamed without waiting).
    [Theory(DisplayName = "PIPELINE-8: a pipelining child cut off or answering garbage mid-stream of parts queries is exit 2, naming the parts op, with no stack trace")]
    [InlineData("serve-cut-after.sh", "closed its stdout instead of answering 'find_cell_parts_transition'")]
    [InlineData("serve-garbage-at.sh", "answered 'find_cell_parts_transition' with something that is not protocol v1")]
    public void PartsStreamBrokenMidwayIsExit2(string script, string message)
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.Script(script) + " 40 " + Acphys.ServeCommand, "--only", "PARTS-INDOOR-COVERAGE", "--timeout", "60"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains(message, run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("   at ", run.Err, StringComparison.Ordinal);
        Assert.DoesNotContain("PASS", run.Out, StringComparison.Ordinal);
    }

    // What a report says per failed invariant: its FAIL line, the shrunk case and the replay seed.
    private static string[] Report(string output) =>
        [.. output.Split('\n').Where(l => l.StartsWith("FAIL ", StringComparison.Ordinal) || l.StartsWith("  shrunk ", StringComparison.Ordinal) || l.StartsWith("  seed ", StringComparison.Ordinal)).Select(l => l.Trim())];

    private static string[] Verdicts(string output) =>
        [.. output.Split('\n').Where(l => l.StartsWith("FAIL ", StringComparison.Ordinal)).Select(l => l.Trim()).Order(StringComparer.Ordinal)];

    private static int Replayed(string err) =>
        ReplayedCount().Match(err) is { Success: true } m ? int.Parse(m.Groups[1].Value, System.Globalization.CultureInfo.InvariantCulture) : throw new InvalidOperationException("no pipeline line in:\n" + err);

    [GeneratedRegex(@"verify: pipeline: \d+ invariant runs streamed, (\d+) replayed")]
    private static partial Regex ReplayedCount();
}
