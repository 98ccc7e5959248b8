using AcPhys.Contract;
using AcPhys.E2E.Support;
using AcPhys.Spec.Faults;

namespace AcPhys.E2E;

/// <summary>
/// The indoor half over protocol v1 with scenes sent as dat records: the record-reading example adapter
/// (examples/dotnet-adapter/RecordAdapter, its own reader) passes the scene invariants, and indoor planted faults served
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

    [Fact(DisplayName = "The record-reading example adapter passes every scene invariant it can be sent; the rest is NOT TESTED")]
    public void RecordAdapterPassesTheSceneInvariants()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", RecordAdapter, "--cases", "400", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        // It offers the scene ops only (static and transition): every scene invariant passes, the rest is not tested.
        Assert.Contains(Expected.CleanSummary(Op.FindCellScene | Op.FindCellTransition), run.Out, StringComparison.Ordinal);
        Assert.Contains("against record-adapter (example)", run.Out, StringComparison.Ordinal);
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
