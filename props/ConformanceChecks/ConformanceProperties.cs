using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using Xunit.Abstractions;

namespace AcPhys.Props.ConformanceChecks;

/// <summary>Each conformance invariant as an FsCheck property: the reference conforms to itself in every mode it can declare.</summary>
public sealed class ConformanceProperties(ITestOutputHelper output)
{
    private static readonly ReferenceAdapter Ace = new(PickPolicy.Retail, outdoor: OutdoorFidelity.Ace) { Indoor = IndoorFidelity.Ace };

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE: every query of every walk, open land and scenes, static and transition, answers as the reference")]
    public void FindCell() => PropertyRun.Check(ConformanceInvariants.FindCell, output);

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE (current-first): the hysteresis pick is compared with the reference's current-first pick")]
    public void FindCellCurrentFirst() => PropertyRun.Check(ConformanceInvariants.FindCell, output, ReferenceAdapter.CurrentFirst);

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE (ACE declared): an implementation declaring every ACE difference is compared in ACE's mode, stale cells exactly (one array per walk)")]
    public void FindCellAce() => PropertyRun.Check(ConformanceInvariants.FindCell, output, Ace);

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE (double declared): the double-precision outdoor arithmetic is compared with its own reference")]
    public void FindCellDouble() => PropertyRun.Check(ConformanceInvariants.FindCell, output, ReferenceAdapter.Double);

    [Fact(DisplayName = "OUTSIDE-CELLS-CONFORMANCE: outside_cells answers the reference's cells in the reference's order")]
    public void OutsideCells() => PropertyRun.Check(ConformanceInvariants.OutsideCells, output);

    [Fact(DisplayName = "FIND-CELL-QUERY-CONFORMANCE: one find_cell query from any kind of position, with and without spheres, answers exactly as the reference")]
    public void FindCellQuery() => PropertyRun.Check(ConformanceInvariants.FindCellQuery, output);

    [Fact(DisplayName = "FIND-CELL-QUERY-CONFORMANCE (current-first, ACE, double declared): each declared mode is compared with the reference in that mode")]
    public void FindCellQueryModes()
    {
        PropertyRun.Check(ConformanceInvariants.FindCellQuery, output, ReferenceAdapter.CurrentFirst);
        PropertyRun.Check(ConformanceInvariants.FindCellQuery, output, Ace);
        PropertyRun.Check(ConformanceInvariants.FindCellQuery, output, ReferenceAdapter.Double);
    }

    [Fact(DisplayName = "LANDDEFS-CONFORMANCE: every LandDefs op answers as the reference")]
    public void LandDefs() => PropertyRun.Check(ConformanceInvariants.LandDefs, output);
}
