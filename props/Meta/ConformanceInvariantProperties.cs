using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using Xunit.Abstractions;

namespace AcPhys.Props.Meta;

/// <summary>The conformance invariants as FsCheck properties against the reference itself (they must hold trivially; a failure is a broken comparison).</summary>
public sealed class ConformanceInvariantProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "LANDDEFS-CONFORMANCE: the reference agrees with itself on every LandDefs operation")]
    public void LandDefs() => PropertyRun.Check(ConformanceInvariants.LandDefs, output);

    [Fact(DisplayName = "OUTSIDE-CELLS-CONFORMANCE: the reference agrees with itself on outside_cells")]
    public void OutsideCells() => PropertyRun.Check(ConformanceInvariants.OutsideCells, output);

    [Fact(DisplayName = "FIND-CELL-CONFORMANCE: the reference agrees with itself on find_cell, static and transition")]
    public void FindCell() => PropertyRun.Check(ConformanceInvariants.FindCell, output);
}
