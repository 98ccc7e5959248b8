using AcPhys.Contract;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Outdoor;

/// <summary>The planted-fault model re-states the retail steps; with no fault switched on it must answer exactly as core, or a "caught fault" could be the model's own bug.</summary>
public sealed class FaultModelMatchesCore
{
    [CiProperty(MaxTest = 3000, DisplayName = "Fault model without a fault: outside_cells equals core's, in insertion order")]
    public Property OutsideCellsMatch()
    {
        var model = PlantedFaults.Model();
        return Prop.ForAll(OutdoorGens.Arbitrary, c =>
            model.OutsideCells(c.Cell, c.Spheres).SequenceEqual(ReferenceAdapter.Instance.OutsideCells(c.Cell, c.Spheres)));
    }

    [CiProperty(MaxTest = 3000, DisplayName = "Fault model without a fault: find_cell equals core's (cells and pick)")]
    public Property FindCellMatches()
    {
        var model = PlantedFaults.Model();
        return Prop.ForAll(OutdoorGens.Arbitrary, c =>
        {
            var a = model.FindCell(c.Cell, c.Spheres, AcPhys.Core.CellId.None);
            var b = ReferenceAdapter.Instance.FindCell(c.Cell, c.Spheres, AcPhys.Core.CellId.None);
            return a.Containing == b.Containing && a.Cells.SequenceEqual(b.Cells);
        });
    }

    [CiProperty(MaxTest = 3000, DisplayName = "Fault model without a fault: every LandDefs answer equals core's")]
    public Property LandDefsMatch()
    {
        var model = PlantedFaults.Model();
        return Prop.ForAll(LandGens.Arbitrary, c =>
        {
            var r = ReferenceAdapter.Instance;
            bool ok1 = model.GetOutsideLcoord(c.Cell, c.X, c.Y, out var l1) == r.GetOutsideLcoord(c.Cell, c.X, c.Y, out var l2) && l1 == l2;
            bool ok2 = model.GidToLcoord(c.Cell, out var g1) == r.GidToLcoord(c.Cell, out var g2) && g1 == g2;
            var a1 = model.AdjustToOutside(c.Cell, c.X, c.Y);
            var a2 = r.AdjustToOutside(c.Cell, c.X, c.Y);
            bool ok3 = a1.Ok == a2.Ok && a1.Cell == a2.Cell && BitConverter.SingleToInt32Bits(a1.X) == BitConverter.SingleToInt32Bits(a2.X) && BitConverter.SingleToInt32Bits(a1.Y) == BitConverter.SingleToInt32Bits(a2.Y);
            return ok1 && ok2 && ok3 && model.LcoordToGid(c.Lcoord.X, c.Lcoord.Y) == r.LcoordToGid(c.Lcoord.X, c.Lcoord.Y) && model.InboundValidCellId(c.Cell) == r.InboundValidCellId(c.Cell);
        });
    }
}
