using AcPhys.Contract;
using AcPhys.Spec.Invariants;

namespace AcPhys.Props.Meta;

/// <summary><see cref="Op.All"/> is every operation (issue 25: it was the open-land ones, so the reference's header read "lacks " and nothing).</summary>
public sealed class OpAllTests
{
    [Fact(DisplayName = "OP-ALL: Op.All holds every single operation flag (the transports are protocol v1's Capability, not operations: issue 42)")]
    public void All_HoldsEveryOperationFlag()
    {
        var flags = Enum.GetValues<Op>().Where(o => o != Op.None && (o & (o - 1)) == 0).ToArray();
        Assert.NotEmpty(flags);
        Assert.All(flags, o => Assert.True((Op.All & o) == o, $"{o} ({string.Join(", ", OpNames.Names(o))}) is not in Op.All"));
        Assert.Equal(flags.Length, OpNames.Names(Op.All).Count);
    }

    [Fact(DisplayName = "OP-ALL: every operation an invariant requires is in Op.All, and the reference offers all of them")]
    public void All_CoversEveryRequirementAndTheReference()
    {
        var required = InvariantCatalogue.All.Aggregate(Op.None, (ops, i) => ops | i.Requires | i.SceneForms);
        Assert.Equal(Op.None, required & ~Op.All);
        Assert.Equal(Op.All, ReferenceAdapter.Instance.Ops & Op.All);
    }

    [Fact(DisplayName = "OP-NAME: each single operation has one protocol name, which parses back to it; a set of flags has none (issue 52: a watchdog named block_id_to_lcoord)")]
    public void Name_IsTheProtocolNameOfOneOperation()
    {
        var flags = Enum.GetValues<Op>().Where(o => o != Op.None && (o & (o - 1)) == 0).ToArray();
        Assert.All(flags, o =>
        {
            string name = OpNames.Name(o);
            Assert.Equal([name], OpNames.Names(o));
            Assert.Equal(o, OpNames.Parse([name], out var unknown));
            Assert.Empty(unknown);
        });
        Assert.Equal("blockid_to_lcoord", OpNames.Name(Op.BlockIdToLcoord));
        Assert.Throws<ArgumentOutOfRangeException>(() => OpNames.Name(Op.LandDefs));
        Assert.Throws<ArgumentOutOfRangeException>(() => OpNames.Name(Op.None));
    }
}
