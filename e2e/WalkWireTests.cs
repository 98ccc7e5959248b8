using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.E2E.Support;
using AcPhys.Formats.Corpus;
using AcPhys.Protocol.Client;
using AcPhys.Protocol.Messages;
using AcPhys.Spec.Cases;

namespace AcPhys.E2E;

/// <summary>
/// find_cell_walk (docs/protocol.md, "Whole walks"): a walk answered whole over protocol v1 is the walk asked query by
/// query; a server without it is asked query by query as before; a failure found through a walk answer still
/// shrinks, prints its seed and replay line, and replays.
/// </summary>
public sealed class WalkWireTests
{
    // Every walk and scene walk of the corpus (seeds, regressions) and the documented examples, plus walks made here to
    // cross block lines from a negative-zero height (the move's z + 0 turns -0 into +0, as the client's add does).
    private static IEnumerable<(string Name, WalkRequest Walk)> Walks()
    {
        var files = new[] { Path.Combine(RepoPaths.Corpus, "seeds"), Path.Combine(RepoPaths.Corpus, "regressions"), Path.Combine(RepoPaths.Root, "docs", "examples") }
            .SelectMany(d => Directory.EnumerateFiles(d, "*.json"))
            .Order(StringComparer.Ordinal);
        foreach (string file in files)
        {
            var entry = CorpusJson.ReadFile(file);
            string name = Path.GetFileName(file);
            if (entry.Walk is { } walk)
            {
                yield return (name, WalkRunner.Request(walk, null));
            }

            if (entry.SceneWalk is { } sw)
            {
                yield return (name + " static", WalkRunner.Request(sw.Walk, sw.Scene));
                yield return (name + " transition", WalkRunner.Request(sw.Walk, sw.Scene, loadCells: true));
            }
        }

        Sphere[] body = [new(new Vector3(0, 0, -0f), 0.5f), new(new Vector3(0.25f, 0, 1), 0.75f)];
        Vector2[] steps = [new(191.9f, 0.1f), new(0.2f, -30), new(-0.1f, 200), new(-400, 0.0001f)];
        yield return ("made: across block lines", new WalkRequest(null, new CellId(0x7F7F0001), new Vector3(1, 2, -0f), body, steps));
        yield return ("made: off the map's west edge", new WalkRequest(null, new CellId(0x00400001), new Vector3(5, 5, 0), body, [new(-10, 0), new(-200, 0), new(1, 1)]));
    }

    [Fact(DisplayName = "WALK-WIRE-1: a walk answered whole by acphys serve is, query for query, the walk asked one query per round trip")]
    public void WholeWalkEqualsQueryByQuery()
    {
        using var whole = ProcessAdapter.Start(Acphys.ServeCommand, new ProcessAdapterOptions { Timeout = TimeSpan.FromSeconds(60) });
        using var single = ProcessAdapter.Start(Acphys.ServeCommand + " --no-walks", new ProcessAdapterOptions { Timeout = TimeSpan.FromSeconds(60) });
        Assert.NotEqual(Capability.None, whole.Capabilities & Capability.FindCellWalk);
        Assert.Equal(Capability.None, single.Capabilities & Capability.FindCellWalk);
        int queries = 0;
        foreach (var (name, walk) in Walks())
        {
            var a = whole.FindCellWalk(walk);
            var b = single.FindCellWalk(walk);
            var reference = ((ICellPhysics)ReferenceAdapter.Instance).FindCellWalk(DatScene(walk, whole));
            Assert.Equal(walk.Queries, a.Count);
            Assert.Equal(walk.Queries, b.Count);
            for (int i = 0; i < a.Count; i++)
            {
                Assert.True(Same(a[i], b[i]) && Same(a[i], reference[i]), $"{name}: query {i}: whole {Text(a[i])}, one by one {Text(b[i])}, in process {Text(reference[i])}");
            }

            queries += a.Count;
        }

        Assert.True(queries > 100, $"only {queries} queries compared");
    }

    [Fact(DisplayName = "WALK-WIRE-2: the runners thread a walk by the documented rule (move, ask from the frame, re-frame by GetBlockOffset on a containing cell)")]
    public void RunnerThreadsByTheDocumentedRule()
    {
        int steps = 0;
        foreach (var (name, walk) in Walks().Where(w => w.Walk.Scene is null))
        {
            // The rule as docs/protocol.md states it, written out here on its own.
            var frame = walk.StartCell;
            var p = walk.Start;
            var current = walk.Current;
            var trace = WalkRunner.Trace(walk, ((ICellPhysics)ReferenceAdapter.Instance).FindCellWalk(walk), loadCells: false);
            for (int i = 0; i < walk.Queries; i++)
            {
                if (i > 0)
                {
                    p = new Vector3(p.X + walk.Steps[i - 1].X, p.Y + walk.Steps[i - 1].Y, p.Z + 0f);
                }

                var spheres = walk.Body.Select(b => new Sphere(new Vector3(p.X + b.Center.X, p.Y + b.Center.Y, p.Z + b.Center.Z), b.Radius)).ToArray();
                var want = ReferenceAdapter.Instance.FindCell(frame, p, spheres, current);
                Assert.True(trace[i].Query.Cell == frame && trace[i].Position == p && Same(trace[i].Answer!, want), $"{name}: step {i}: runner asked {trace[i].Query} at {trace[i].Position}, the rule asks {frame} at {p}");
                if (!want.Containing.IsNone)
                {
                    p = new Vector3(p.X - (192f * (want.Containing.BlockX - frame.BlockX)), p.Y - (192f * (want.Containing.BlockY - frame.BlockY)), p.Z - 0f);
                    frame = current = want.Containing;
                }

                steps++;
            }
        }

        Assert.True(steps > 20, $"only {steps} steps checked");
    }

    [RequiresPythonFact(DisplayName = "WALK-WIRE-3: an implementation that does not announce find_cell_walk is asked query by query and judged as before")]
    public void ImplementationWithoutWalksIsJudgedAsBefore()
    {
        const string OldOps = "blockid_to_lcoord,gid_to_lcoord,lcoord_to_gid,inbound_valid_cellid,get_outside_lcoord,adjust_to_outside,outside_cells,find_cell";
        string[] only = ["--only", "NO-BOUNDARY-FREEZE,WALK-REVERSIBLE,FIND-CELL-CONFORMANCE", "--cases", "300", "--timeout", "60", "--max-classes", "1"];
        var clean = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample + " --ops " + OldOps, .. only]);
        Assert.True(clean.Exit == 0, clean.ToString());
        Assert.DoesNotContain("find_cell_walk", clean.Out, StringComparison.Ordinal);
        var old = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample + " --bug clamp-106 --ops " + OldOps, .. only]);
        var now = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample + " --bug clamp-106 --ops " + OldOps + ",find_cell_walk", .. only]);
        Assert.True(old.Exit == 1 && now.Exit == 1, old + "\n" + now);
        static string[] Failed(Run r) => [.. r.Out.Split('\n').Where(l => l.StartsWith("FAIL ", StringComparison.Ordinal)).Select(l => l.Trim()).Order(StringComparer.Ordinal)];
        Assert.Contains("FAIL NO-BOUNDARY-FREEZE on python-example+clamp-106", Failed(old));
        Assert.Equal(Failed(old), Failed(now));
    }

    [Fact(DisplayName = "WALK-WIRE-4: a failure found through a walk answer shrinks, prints its seed and replay line, and the replay fails the same way")]
    public void WalkAnswerFailureShrinksAndReplays()
    {
        string serve = Acphys.ServeCommand + " --fault clamp-106";
        var run = Acphys.Run(["verify", "--impl-cmd", serve, "--only", "NO-BOUNDARY-FREEZE", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("find_cell_walk", run.Out, StringComparison.Ordinal); // the walks travelled whole
        string shrunk = Line(run.Out, "  shrunk     start ");
        string steps = shrunk[(shrunk.IndexOf("steps [", StringComparison.Ordinal) + 7)..].TrimEnd(']');
        Assert.True(steps.Split(';').Length <= 2, shrunk);
        var again = Acphys.Run(["verify", "--impl-cmd", serve, "--only", "NO-BOUNDARY-FREEZE", "--seed", ReplayOutput.Seed(run.Out), "--timeout", "60"]);
        Assert.True(again.Exit == 1, again.ToString());
        Assert.Contains(shrunk.Trim(), again.Out, StringComparison.Ordinal);
    }

    private static WalkRequest DatScene(WalkRequest walk, ProcessAdapter served) =>
        walk.Scene is null || (served.Capabilities & Capability.DatRecords) == 0 ? walk : walk with { Scene = AcPhys.Formats.Dat.DatRoundTrip.Of(walk.Scene) };

    private static bool Same(FindCellResult a, FindCellResult b) =>
        a.Cells.SequenceEqual(b.Cells) && a.Containing == b.Containing && a.HitsInteriorCell == b.HitsInteriorCell
        && (a.Loaded ?? []).SequenceEqual(b.Loaded ?? []);

    private static string Text(FindCellResult r) => $"[{string.Join(", ", r.Cells)}] -> {r.Containing}";

    private static string Line(string text, string prefix) =>
        text.Split('\n').FirstOrDefault(l => l.StartsWith(prefix, StringComparison.Ordinal)) ?? throw new Xunit.Sdk.XunitException($"no line starting '{prefix}' in:\n{text}");
}
