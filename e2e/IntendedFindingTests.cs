using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// Issue #29, actionable findings: a conformance finding names the documented deviation whose declaration would make
/// it intended (the case re-judged with the port's answers under each switch); a port that declares it passes.
/// </summary>
public sealed class IntendedFindingTests
{
    [Fact]
    public void AnUndeclaredTransitionFilterIsReportedWithTheSwitchThatMakesItIntended()
    {
        // The reference filtering its transitions as ACE does (facts §7 #9) but announcing retail.
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fidelity ace-transition-filter --announce-retail", "--only", "FIND-CELL-CONFORMANCE", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("transition find_cell from", run.Out, StringComparison.Ordinal);
        Assert.Contains("  intended   your answers are the reference's if you declare \"fidelity\": [\"ace-transition-filter\"] in hello", run.Out, StringComparison.Ordinal);
    }

    [Fact]
    public void APortDeclaringAceAndServingTransitionsPassesFindCellConformance()
    {
        // Issue #29 done-when: the transition filter is part of ace, so the declared port is compared with ACE's transitions.
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fidelity ace", "--only", "FIND-CELL-CONFORMANCE", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("verify: 1 invariant, 1 passed, 0 failed, 0 not tested", run.Out, StringComparison.Ordinal);
        Assert.DoesNotContain("capabilities:", run.Out, StringComparison.Ordinal); // every op offered, find_cell_transition included
    }

    [Fact(DisplayName = "INTENDED-PROVED: ACE's box-side pairing served undeclared (serve --fault ace-box-side-undeclared) fails PARTS-INDOOR-CONFORMANCE over protocol v1, and the intended line names ace-box-side-pairing")]
    public void AnUndeclaredBoxSidePairingIsNamed()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fault ace-box-side-undeclared", "--only", "PARTS-INDOOR-CONFORMANCE", "--cases", "300", "--timeout", "60", "--max-classes", "1"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("find_cell_parts_", run.Out, StringComparison.Ordinal);
        Assert.Contains("  intended   your answers are the reference's if you declare \"fidelity\": [\"ace-box-side-pairing\"] in hello", run.Out, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "INTENDED-PROVED: the reference serving ACE's box-side pairing and declaring it (serve --fidelity ace-box-side-pairing) passes PARTS-INDOOR-CONFORMANCE over protocol v1")]
    public void ADeclaredBoxSidePairingPasses()
    {
        var run = Acphys.Run(["verify", "--impl-cmd", Acphys.ServeCommand + " --fidelity ace-box-side-pairing", "--only", "PARTS-INDOOR-CONFORMANCE", "--cases", "300", "--timeout", "60"]);
        Assert.True(run.Exit == 0, run.ToString());
        Assert.Contains("verify: 1 invariant, 1 passed, 0 failed, 0 not tested", run.Out, StringComparison.Ordinal);
    }

    [Theory(DisplayName = "INTENDED-PROVED (issue 41): a planted fault served under a declaration still fails, and its intended line names no declaration but says what differs")]
    [InlineData("close-is-outside", "ace")]
    [InlineData("snapshot-closure", "ace-keeps-stale-cells")]
    [InlineData("touch-inclusive", "double")]
    public void AServedFaultIsNeverIntended(string fault, string declaration)
    {
        var run = Acphys.Run(["verify", "--impl-cmd", $"{Acphys.ServeCommand} --fault {fault} --fidelity {declaration}", "--only", "FIND-CELL-CONFORMANCE,FIND-CELL-QUERY-CONFORMANCE", "--cases", "300", "--timeout", "60", "--max-classes", "1"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.DoesNotContain("your answers are the reference's if you declare", run.Out, StringComparison.Ordinal);
        Assert.Contains("  intended   no: ", run.Out, StringComparison.Ordinal);
    }

    [Theory(DisplayName = "INTENDED-PROVED (issue 41): a parts fault indoors served under a declaration fails PARTS-INDOOR-CONFORMANCE, and its intended line names no declaration but says what differs")]
    [InlineData("parts-order-lost", "ace")]
    [InlineData("parts-first-part-only", "ace-neighbour-via-visible-cells")]
    [InlineData("parts-gate-two-sided", "ace-box-side-pairing")]
    public void AServedPartsFaultIsNeverIntended(string fault, string declaration)
    {
        var run = Acphys.Run(["verify", "--impl-cmd", $"{Acphys.ServeCommand} --fault {fault} --fidelity {declaration}", "--only", "PARTS-INDOOR-CONFORMANCE", "--cases", "300", "--timeout", "60", "--max-classes", "1"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("find_cell_parts_", run.Out, StringComparison.Ordinal);
        Assert.DoesNotContain("your answers are the reference's if you declare", run.Out, StringComparison.Ordinal);
        Assert.Contains("  intended   no: ", run.Out, StringComparison.Ordinal);
    }
}
