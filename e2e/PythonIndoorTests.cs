using System.Xml.Linq;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// The Python example's indoor half (examples/python/acphys_indoor.py, and acphys_parts.py for the parts variant in a
/// scene) over protocol v1: a second-language port of the scene queries is judged on every scene invariant, its seeded indoor bug fails the gate, and an answer field it
/// leaves out makes the invariant that needs it NOT TESTED with the field named, never PASS.
/// </summary>
public sealed class PythonIndoorTests
{
    // Every scene invariant, the two current-first ones included (NOT TESTED: the example declares the retail pick), and
    // the four over the parts variant in a scene (issue 41: find_cell_parts_scene and find_cell_parts_transition).
    private const string SceneInvariants =
        "INTERIOR-WINS,HYSTERESIS-INDOOR,PORTAL-TRANSIT,NO-TUNNEL,VISIBILITY,ENTER-EXIT,SCENE-TRANSLATION,CONTAINING-CONTAINS,NEVER-NULL,SCENE-SOUNDNESS,"
        + "NEIGHBOURS-COMPLETE,BUILDING-ENTRY-COMPLETE,ENV-CANDIDATE-JUSTIFIED,HITS-INTERIOR,LAND-VIA-EXIT,PICK-FIRST-ENV,FIND-CELL-CONFORMANCE,"
        + "PARTS-INDOOR-SOUNDNESS,PARTS-INDOOR-COVERAGE,PARTS-BUILDING-ENTRY,PARTS-INDOOR-CONFORMANCE";

    [RequiresPythonFact(DisplayName = "PY-INDOOR-1: the Python example passes every scene invariant it can be judged on, static and as transitions, the parts variant included")]
    public void PythonExamplePassesEverySceneInvariant()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample, "--only", SceneInvariants, "--cases", "40", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.DoesNotContain("capabilities:", run.Out, StringComparison.Ordinal); // every op offered, outside_cells_parts included (no "lacks" line)
        Assert.Contains(",outside_cells_parts,", run.Err, StringComparison.Ordinal); // as its hello announced it (its stderr log)
        Assert.Contains("verify: 21 invariants, 19 passed, 0 failed, 2 not tested", run.Out, StringComparison.Ordinal);
        Assert.Contains("NOT TESTED HYSTERESIS-INDOOR: applies to the current-first pick", run.Out, StringComparison.Ordinal);
    }

    [RequiresPythonFact(DisplayName = "PY-INDOOR-2: the example's seeded indoor bug (PortalSide read backwards) fails the gate, which names PORTAL-TRANSIT")]
    public void PythonPortalSideBugFailsTheGate()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample + " --bug portal-side-inverted", "--only", "PORTAL-TRANSIT", "--cases", "300", "--timeout", "60", "--max-classes", "1"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("FAIL PORTAL-TRANSIT on python-example+portal-side-inverted", run.Out, StringComparison.Ordinal);
        Assert.Contains(", 0 passed, 1 failed, 0 not tested", run.Out, StringComparison.Ordinal);
    }

    [RequiresPythonFact(DisplayName = "PY-INDOOR-3: HITS-INTERIOR is NOT TESTED naming hits_interior_cell, counted apart in the summary, skipped with the reason in JUnit and listed in the markdown")]
    public void MissingAnswerFieldIsNotTestedWithTheReason()
    {
        string dir = Directory.CreateTempSubdirectory("acphys-py-indoor-").FullName;
        string junit = Path.Combine(dir, "out.xml"), markdown = Path.Combine(dir, "summary.md");
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.PythonExample, "--only", "HITS-INTERIOR,VISIBILITY", "--cases", "40", "--timeout", "60", "--junit", junit, "--markdown", markdown]);
        Assert.True(run.Exit == 0, run.ToString());

        const string Reason = "none of the 40 generated cases could judge it (the implementation does not report hits_interior_cell)";
        Assert.Contains("NOT TESTED HITS-INTERIOR: " + Reason, run.Out, StringComparison.Ordinal);
        Assert.Matches(@"│ HITS-INTERIOR +│ +- │ +- │ +- +│ NOT TESTED │", run.Out);
        Assert.Contains("verify: 2 invariants, 1 passed, 0 failed, 1 not tested", run.Out, StringComparison.Ordinal);

        var suite = XDocument.Load(junit).Root!.Element("testsuite")!;
        Assert.Equal(("2", "0", "1"), (suite.Attribute("tests")!.Value, suite.Attribute("failures")!.Value, suite.Attribute("skipped")!.Value));
        var skipped = suite.Elements("testcase").Single(t => t.Attribute("name")!.Value == "HITS-INTERIOR").Element("skipped");
        Assert.Equal("not tested: " + Reason, skipped?.Attribute("message")?.Value);
        Assert.Null(suite.Elements("testcase").Single(t => t.Attribute("name")!.Value == "VISIBILITY").Element("skipped"));

        string md = File.ReadAllText(markdown);
        Assert.Contains("1 passed, 0 failed, 1 not tested.", md, StringComparison.Ordinal);
        Assert.Contains("- `HITS-INTERIOR`: " + Reason, md, StringComparison.Ordinal);
    }
}
