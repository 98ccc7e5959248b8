using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// Issue 53: ace-keeps-stale-cells for the parts lists over protocol v1. A served reference declaring it answers each
/// walk's parts queries through <c>find_cell_parts_walk</c> (one array per walk and kind, facts §7 #6) and passes the
/// four PARTS-INDOOR invariants; the planted fault <c>parts-stale-cleared</c> served fails; a child declaring it that
/// would be asked its parts queries one by one is refused at the handshake.
/// </summary>
public sealed class PartsStaleCellsServedTests
{
    private const string PartsIndoor = "PARTS-INDOOR-SOUNDNESS,PARTS-INDOOR-COVERAGE,PARTS-BUILDING-ENTRY,PARTS-INDOOR-CONFORMANCE";

    [Fact(DisplayName = "PARTS-INDOOR-*: the reference served declaring ace-keeps-stale-cells passes all four (its parts walks asked whole, exit 0)")]
    public void StaleReferenceServedPasses()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", $"{Acphys.ServeCommand} --fidelity ace-keeps-stale-cells", "--only", PartsIndoor, "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 0, $"serve --fidelity ace-keeps-stale-cells: expected a pass: {run}");
        Assert.Contains("4 passed, 0 failed, 0 not tested", run.Out, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "PARTS-INDOOR-CONFORMANCE: parts-stale-cleared served (declares ace-keeps-stale-cells, clears the parts list each query) fails (exit 1)")]
    public void ClearedFaultServedFails()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", $"{Acphys.ServeCommand} --fault parts-stale-cleared", "--only", "PARTS-INDOOR-CONFORMANCE", "--cases", "300", "--max-classes", "1", "--timeout", "60"]);
        Assert.True(run.Exit == 1, $"serve --fault parts-stale-cleared: expected PARTS-INDOOR-CONFORMANCE to fail (exit 1): {run}");
        Assert.Contains("FAIL PARTS-INDOOR-CONFORMANCE", run.Out, StringComparison.Ordinal);
    }

    [Theory(DisplayName = "ace-keeps-stale-cells: a child that declares it and offers the parts kinds but would be asked them one by one (no find_cell_parts_walk, or the world frame) is refused at the handshake (exit 2)")]
    [InlineData("--no-walks")]
    [InlineData("--world-frame")]
    public void StalePartsNeedWholeWalks(string transport)
    {
        var run = Acphys.Run(["verify", "--impl-cmd", $"{Acphys.ServeCommand} --fidelity ace-keeps-stale-cells --ops find_cell_parts_scene,find_cell_parts_transition {transport}", "--only", "PARTS-INDOOR-CONFORMANCE", "--cases", "10", "--timeout", "60"]);
        Assert.True(run.Exit == 2, $"serve --fidelity ace-keeps-stale-cells (parts only) {transport}: expected exit 2: {run}");
        Assert.Contains("declares ace-keeps-stale-cells but would be asked its parts queries one by one", run.Err, StringComparison.Ordinal);
    }
}
