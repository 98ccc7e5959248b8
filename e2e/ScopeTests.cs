using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>Issue #18: <c>verify --scope</c> keeps retail statements and hardening rules apart.</summary>
public sealed class ScopeTests
{
    [Fact(DisplayName = "SCOPE: --scope hardening runs only hardening rules and the report counts each scope apart; a port that accepts NaN as retail does fails only them")]
    public void HardeningScopeRunsOnlyHardeningRules()
    {
        var run = Acphys.Run(["verify", "--fault", "nan-as-zero", "--scope", "hardening", "--cases", "400", "--quiet"]);
        Assert.True(run.Exit == 1, run.ToString());
        Assert.Contains("FAIL NONFINITE-REJECTED", run.Out, StringComparison.Ordinal);
        Assert.DoesNotContain("FAIL OUTSIDE-LCOORD-GEOMETRY", run.Out, StringComparison.Ordinal);
        Assert.Contains("by scope: retail 0 passed, 0 failed, 0 not tested; hardening ", run.Out, StringComparison.Ordinal);

        var retail = Acphys.Run(["verify", "--fault", "nan-as-zero", "--scope", "retail", "--only", "OUTSIDE-LCOORD-GEOMETRY,ADJUST-GEOMETRY,LANDDEFS-CONFORMANCE,NONFINITE-REJECTED", "--cases", "2000", "--quiet"]);
        Assert.True(retail.Exit == 0, retail.ToString()); // NONFINITE-REJECTED is left out by the scope; the retail ones hold
        Assert.Contains("verify: 3 invariants, 3 passed", retail.Out, StringComparison.Ordinal);
    }

    [Fact(DisplayName = "SCOPE: an unknown --scope value is a usage error (exit 2) naming the known values")]
    public void UnknownScopeIsAUsageError()
    {
        var run = Acphys.Run(["verify", "--scope", "bogus"]);
        Assert.True(run.Exit == 2, run.ToString());
        Assert.Contains("unknown scope 'bogus' (known: retail, hardening, all)", run.Err, StringComparison.Ordinal);
    }
}
