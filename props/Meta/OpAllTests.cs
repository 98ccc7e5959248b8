using AcPhys.Spec.Adapters;
using AcPhys.Spec.Invariants;

namespace AcPhys.Props.Meta;

/// <summary><see cref="Op.All"/> is every operation (issue 25: it was the open-land ones, so the reference's header read "lacks " and nothing).</summary>
public sealed class OpAllTests
{
    /// <summary>Transports of a scene, not operations an invariant needs (Op.cs).</summary>
    private const Op Transports = Op.LoadScene | Op.DatRecords | Op.FindCellWalk | Op.Pipeline;

    [Fact(DisplayName = "OP-ALL: Op.All holds every single operation flag but the scene transports")]
    public void All_HoldsEveryOperationFlag()
    {
        var flags = Enum.GetValues<Op>().Where(o => o != Op.None && (o & (o - 1)) == 0 && (o & Transports) == 0).ToArray();
        Assert.NotEmpty(flags);
        Assert.All(flags, o => Assert.True((Op.All & o) == o, $"{o} ({string.Join(", ", OpNames.Names(o))}) is not in Op.All"));
        Assert.Equal(Op.None, Op.All & Transports);
    }

    [Fact(DisplayName = "OP-ALL: every operation an invariant requires is in Op.All, and the reference offers all of them")]
    public void All_CoversEveryRequirementAndTheReference()
    {
        var required = InvariantCatalogue.All.Aggregate(Op.None, (ops, i) => ops | i.Requires | i.SceneForms);
        Assert.Equal(Op.None, required & ~Op.All);
        Assert.Equal(Op.All, ReferenceAdapter.Instance.Ops & Op.All);
    }
}
