using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Props.Meta;

/// <summary>Issue #29: a verdict never overstates — an invariant no generated case could judge is NOT TESTED, with the reason.</summary>
public sealed class NoPassWithoutACase
{
    [Fact(DisplayName = "HITS-INTERIOR: a port that does not report hits_interior_cell is NOT TESTED, the missing field named, never PASS")]
    public void MissingAnswerFieldIsNotTested()
    {
        var seed = PropertyRun.SeedFor("HITS-INTERIOR");
        var silent = IndoorExactInvariants.HitsInterior.Run(new NoHitsField(), 300, seed);
        Assert.Equal(ResultStatus.NotTested, silent.Status);
        Assert.Contains("hits_interior_cell", silent.NotTestedReason);
        Assert.Equal(0, silent.Applicable);

        var reporting = IndoorExactInvariants.HitsInterior.Run(ReferenceAdapter.Instance, 300, seed);
        Assert.Equal(ResultStatus.Passed, reporting.Status);
        Assert.True(reporting.Applicable > 0);
    }

    [Fact(DisplayName = "A failing invariant counts its violating case as applicable (no 'Applicable 0' beside FAIL)")]
    public void AFailureIsApplicable()
    {
        var caught = IndoorExactInvariants.HitsInterior.Run(new AlwaysOutside(), 300, PropertyRun.SeedFor("HITS-INTERIOR"), maxClasses: 1);
        Assert.Equal(ResultStatus.Failed, caught.Status);
        Assert.True(caught.Applicable > 0, $"applicable {caught.Applicable} beside FAIL");
    }

    // The reference's answers with hits_interior_cell left out, as protocol v1 allows.
    private sealed class NoHitsField() : Forwarding(ReferenceAdapter.Instance)
    {
        public override FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
            Inner.FindCell(scene, cell, spheres, current, loadCells) with { HitsInteriorCell = null };
    }

    // Reports HitsInteriorCell false on every answer.
    private sealed class AlwaysOutside() : Forwarding(ReferenceAdapter.Instance)
    {
        public override FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
            Inner.FindCell(scene, cell, spheres, current, loadCells) with { HitsInteriorCell = false };
    }
}
