using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// The parts frame faults (issue 41 follow-up: a port misreading a part's rotation, box or cell) served over protocol
/// v1 are caught by the independent PARTS-INDOOR invariants, as in process (docs/bite.md).
/// </summary>
public sealed class PartsFrameFaultsServedTests
{
    [Theory(DisplayName = "PARTS-INDOOR-SOUNDNESS / PARTS-INDOOR-COVERAGE: a parts frame fault served by acphys serve --fault fails both independent invariants (exit 1)")]
    [InlineData("parts-rotation-inverted")]
    [InlineData("parts-yaw-only")]
    [InlineData("parts-box-centred")]
    [InlineData("parts-anchor-frame")]
    public void FrameFaultIsCaughtServed(string fault)
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault " + fault, "--only", "PARTS-INDOOR-SOUNDNESS,PARTS-INDOOR-COVERAGE", "--cases", "300", "--max-classes", "1", "--timeout", "60"]);
        Assert.True(run.Exit == 1, $"{fault}: {run}");
        Assert.Contains("FAIL PARTS-INDOOR-SOUNDNESS", run.Out, StringComparison.Ordinal);
        Assert.Contains("FAIL PARTS-INDOOR-COVERAGE", run.Out, StringComparison.Ordinal);
    }
}
