using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// The parts faults of issue 53 (retail-like part shapes and anchors: spec/Faults/PartsShapeFaults; Always2D parts
/// indoors and parts held in another env cell: spec/Faults/PartsObjectFaults) served over protocol v1 are caught by
/// every invariant they name, as in process (props PartsFaultsAreCaught).
/// </summary>
public sealed class PartsShapeFaultsServedTests
{
    [Theory(DisplayName = "PARTS-INDOOR-CONFORMANCE (and the independent PARTS-INDOOR invariants where named): a parts shape, anchor, Always2D or held-part fault served by acphys serve --fault fails every invariant it names (exit 1)")]
    [InlineData("parts-box-before-gate")]
    [InlineData("parts-gate-two-sided")]
    [InlineData("parts-neighbour-by-sphere")]
    [InlineData("parts-box-side-skipped")]
    [InlineData("parts-missing-anchor-empty")]
    [InlineData("parts-always2d-ignored-indoors")]
    [InlineData("parts-own-cell-frame")]
    [InlineData("parts-env-block-offset-dropped")]
    public void ShapeFaultIsCaughtServed(string fault)
    {
        var caughtBy = AcPhys.Spec.Faults.PlantedFaults.Find(fault)!.CaughtBy;
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault " + fault, "--only", string.Join(',', caughtBy), "--cases", "300", "--max-classes", "1", "--timeout", "60"]);
        Assert.True(run.Exit == 1, $"{fault}: {run}");
        foreach (var id in caughtBy)
        {
            Assert.Contains("FAIL " + id, run.Out, StringComparison.Ordinal);
        }

        Assert.Contains("find_cell_parts_", run.Out, StringComparison.Ordinal);
    }
}
