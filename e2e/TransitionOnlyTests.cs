using System.Numerics;
using System.Text.Json;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.E2E.Support;
using AcPhys.Formats.Scenes;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Server;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Scenes;

namespace AcPhys.E2E;

/// <summary>
/// Issue #29, query kinds a port declares: a port whose only scene query is the movement transition
/// (find_cell_transition without find_cell_scene) is gated on transitions over protocol v1 — every scene invariant
/// with a transition form runs there (retail's rule: no visibility filter, facts §4 step 5, §6.14), only the
/// static-only VISIBILITY is NOT TESTED with its reason, and faults that break transitions are caught.
/// </summary>
public sealed class TransitionOnlyTests
{
    /// <summary>Every operation of the reference but static placement: the shape of a client's transition-only FindCellSet.</summary>
    private static readonly Op TransitionOnly = Op.All & ~Op.FindCellScene;

    private static string Serve(string extra = "") =>
        $"{Acphys.ServeCommand} --ops {string.Join(",", OpNames.Names(TransitionOnly))}{extra}";

    [Fact]
    public void TransitionOnlyReferenceIsFullyGatedWithNoFailureForWantOfTheStaticQuery()
    {
        // 300 cases: at 100 the pr stream (issue 40's low-word bounds) leaves NONFINITE-SPHERE-ENDS-LOOP without a judged case.
        var run = Acphys.Run(["verify", "--impl-cmd", Serve(), "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("; lacks find_cell_scene", run.Out, StringComparison.Ordinal);
        Assert.Contains(Expected.CleanSummary(TransitionOnly), run.Out, StringComparison.Ordinal);
        Assert.Contains("NOT TESTED VISIBILITY: states static placement only (find_cell_scene); implementation offers find_cell_transition", run.Out, StringComparison.Ordinal);
        Assert.DoesNotContain("lacks find_cell_scene or", run.Out, StringComparison.Ordinal); // no scene invariant skipped for want of the static query
        Assert.Contains("NOT TESTED HYSTERESIS-INDOOR: applies to the current-first pick", run.Out, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("snapshot-closure", "NEIGHBOURS-COMPLETE")]
    [InlineData("no-exit-transit", "ENTER-EXIT")]
    public void TransitFaultIsCaughtOnTransitionsAlone(string fault, string independent)
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Serve(" --fault " + fault), "--only", $"{independent},LAND-VIA-EXIT,FIND-CELL-CONFORMANCE", "--cases", "200", "--timeout", "60"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains($"FAIL {independent} on reference+{fault} (without find_cell_scene)", run.Out, StringComparison.Ordinal);
        Assert.Contains($"FAIL FIND-CELL-CONFORMANCE on reference+{fault} (without find_cell_scene)", run.Out, StringComparison.Ordinal);
        Assert.Contains("transition find_cell from", run.Out, StringComparison.Ordinal); // judged on a transition query
        Assert.DoesNotContain("static find_cell from", run.Out, StringComparison.Ordinal);
        Assert.DoesNotContain("your answers are the reference's if you declare", run.Out, StringComparison.Ordinal); // a port bug: no declaration makes it intended
    }

    [Fact]
    public void EveryInvariantWithATransitionFormIsTestableOnTransitionsAlone()
    {
        // Only VISIBILITY (the static filter itself) and the pick-bound HYSTERESIS-INDOOR stay out, each with its reason.
        var scene = InvariantCatalogue.All.Where(i => i.SceneForms != Op.None).ToList();
        Assert.NotEmpty(scene);
        var untested = scene.Where(i => i.WhyNotTestable(TransitionOnly, PickPolicy.Retail) is not null).Select(i => i.Id).ToList();
        Assert.Equal(["HYSTERESIS-INDOOR", "VISIBILITY"], untested.Order());
        Assert.Null(InvariantCatalogue.All.Single(i => i.Id == "HYSTERESIS-INDOOR").WhyNotTestable(TransitionOnly, PickPolicy.CurrentFirst));
        Assert.Equal(
            "states the movement transition only (find_cell_transition); implementation offers find_cell_scene",
            InvariantCatalogue.All.Single(i => i.Id == "LAND-VIA-EXIT").WhyNotTestable(Op.All & ~Op.FindCellTransition, PickPolicy.Retail));
        Assert.Equal("implementation lacks find_cell_scene or find_cell_transition", scene[0].WhyNotTestable(Op.OpenLand, PickPolicy.Retail));
    }

    [Fact]
    public void ServerOfATransitionOnlyPortLoadsScenesAndRefusesStaticPlacement()
    {
        var plan = new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0.3f, 2, 6f, 6f, 0, true, false);
        var scene = SceneKit.Cottage(plan);
        var server = new ProtocolServer(new OpsOffered(ReferenceAdapter.Instance, TransitionOnly)) { DatRecords = false };
        using var hello = JsonDocument.Parse(server.Answer("{\"op\":\"hello\",\"protocol\":1}"));
        var ops = hello.RootElement.GetProperty("ops").EnumerateArray().Select(e => e.GetString()).ToList();
        Assert.Contains("load_scene", ops);
        Assert.Contains("find_cell_transition", ops);
        Assert.DoesNotContain("find_cell_scene", ops);
        using var loaded = Wire.Parse(server.Answer(Wire.Line(w =>
        {
            w.WriteString("op", "load_scene");
            w.WritePropertyName("scene");
            w.WriteRawValue(SceneJson.WriteCompact(scene));
        })));
        string id = Wire.ReadString(loaded.RootElement, "scene_id");
        var spheres = new[] { new Sphere(plan.ToBlock(new Vector3(3, 3, 0.6f)), 0.5f) };
        string Ask(bool loadCells) => server.Answer(Wire.Line(w =>
        {
            w.WriteString("op", "find_cell");
            w.WriteString("scene_id", id);
            Wire.WriteCell(w, "cell", plan.RoomId(0));
            Wire.WriteSpheres(w, "spheres", spheres);
            w.WriteNull("current");
            w.WriteBoolean("load_cells", loadCells);
        }));
        Assert.StartsWith("{\"error\":\"static placement (find_cell_scene) not offered", Ask(false), StringComparison.Ordinal);
        using var answer = Wire.Parse(Ask(true));
        var expected = ReferenceAdapter.Instance.FindCell(scene, plan.RoomId(0), spheres, CellId.None, true);
        Assert.Equal(expected.Cells, Wire.ReadFindCell(answer.RootElement).Cells);
    }
}
