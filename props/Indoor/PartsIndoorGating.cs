using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Invariants;

namespace AcPhys.Props.Indoor;

/// <summary>The parts invariants indoors are gated on either parts kind: a port without both is NOT TESTED naming them, one kind suffices.</summary>
public sealed class PartsIndoorGating
{
    private static readonly string[] Ids = ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"];

    [Fact(DisplayName = "PARTS-INDOOR-*: NOT TESTED without find_cell_parts_scene and find_cell_parts_transition (both named); testable with either one alone")]
    public void GatedOnEitherKind()
    {
        foreach (var id in Ids)
        {
            var invariant = InvariantCatalogue.Find(id)!;
            Assert.Equal("implementation lacks find_cell_parts_scene or find_cell_parts_transition", invariant.WhyNotTestable(Op.All & ~(Op.FindCellPartsScene | Op.FindCellPartsTransition), PickPolicy.Retail));
            Assert.Null(invariant.WhyNotTestable(Op.FindCellPartsScene, PickPolicy.Retail));
            Assert.Null(invariant.WhyNotTestable(Op.FindCellPartsTransition, PickPolicy.Retail));
            Assert.Contains(invariant, InvariantCatalogue.SceneInvariants);
        }
    }
}
