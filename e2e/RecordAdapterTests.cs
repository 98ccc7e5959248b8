using AcPhys.Contract;
using AcPhys.E2E.Support;
using AcPhys.Spec.Faults;

namespace AcPhys.E2E;

/// <summary>
/// The indoor half over protocol v1 with scenes sent as dat records: the record-reading example adapter
/// (examples/dotnet-adapter/RecordAdapter, its own reader) passes the scene invariants, the parts ones included, and
/// its seeded parts bug is caught; indoor planted faults served
/// by <c>acphys serve --fault</c> (which announces dat_records, so it reads every scene from the records) are caught
/// by the same invariant as in process.
/// </summary>
public sealed class RecordAdapterTests
{
    private static string RecordAdapter
    {
        get
        {
            string configuration = AppContext.BaseDirectory.Contains("/Debug/", StringComparison.Ordinal) ? "Debug" : "Release";
            return "dotnet " + Path.Combine(RepoPaths.Root, "examples", "dotnet-adapter", "RecordAdapter", "bin", configuration, "net10.0", "RecordAdapter.dll");
        }
    }

    private static readonly string[] PartsIndoor = ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"];

    [Fact(DisplayName = "The record-reading example adapter passes every scene invariant it can be sent, the four PARTS-INDOOR ones included; the rest is NOT TESTED")]
    public void RecordAdapterPassesTheSceneInvariants()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", RecordAdapter, "--cases", "400", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        // It offers the scene ops (static and transition) and the parts variant in a scene (both kinds): every scene
        // invariant passes, the rest is not tested.
        var ops = Op.FindCellScene | Op.FindCellTransition | Op.FindCellPartsScene | Op.FindCellPartsTransition;
        Assert.Contains(Expected.CleanSummary(ops), run.Out, StringComparison.Ordinal);
        Assert.Contains("against record-adapter (example)", run.Out, StringComparison.Ordinal);
        foreach (string id in PartsIndoor)
        {
            Assert.Matches($"│ {id} +│.*│ PASS +│", run.Out);
        }
    }

    // The adapter's seeded bug ACPHYS_EXAMPLE_BUG=parts-anchor-only answers each parts query with the first part alone:
    // a port that drops the rest of the object. Its parts list then misses the cells a later part's box reaches.
    [Fact(DisplayName = "PARTS-INDOOR-COVERAGE: the record-reading adapter answering the parts variant with its anchor part alone fails the gate")]
    public void RecordAdapterDroppingPartsIsCaught()
    {
        var bug = new Dictionary<string, string> { ["ACPHYS_EXAMPLE_BUG"] = "parts-anchor-only" };
        var run = Acphys.Run(["verify", "--impl-cmd", RecordAdapter, "--only", "PARTS-INDOOR-COVERAGE", "--timeout", "60", "--max-classes", "1"], bug);
        Assert.True(run.Exit == 1, $"parts-anchor-only: expected PARTS-INDOOR-COVERAGE to fail (exit 1): {run}");
        Assert.Contains("FAIL PARTS-INDOOR-COVERAGE", run.Out, StringComparison.Ordinal);
        Assert.Contains("is missing from", run.Out, StringComparison.Ordinal);
    }

    // One fault per part of the indoor path: building entry (loop, portal test), BSP pieces, transit frames, closure.
    [Theory(DisplayName = "An indoor planted fault served from dat records is caught by its first independent invariant, as in process")]
    [InlineData("building-stop-first-room")]
    [InlineData("walks-negative-children")]
    [InlineData("neighbour-wrong-frame")]
    [InlineData("snapshot-closure")]
    [InlineData("invalid-bld-portal-entered")]
    public void IndoorFaultIsCaughtFromRecords(string fault)
    {
        string catcher = PlantedFaults.Find(fault)!.CaughtBy.First(id => !id.EndsWith("-CONFORMANCE", StringComparison.Ordinal));
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault " + fault, "--only", catcher, "--timeout", "60", "--max-classes", "1"]);
        Assert.True(run.Exit == 1, $"{fault} over dat records: expected {catcher} to fail (exit 1): {run}");
        Assert.Contains($"FAIL {catcher}", run.Out, StringComparison.Ordinal);
    }
}
