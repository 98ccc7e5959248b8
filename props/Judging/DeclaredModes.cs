using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;

namespace AcPhys.Props.Judging;

/// <summary>The reference in a declared mode, and the same reference serving that mode while declaring retail.</summary>
internal static class DeclaredModes
{
    /// <summary>Returns the reference declaring one fidelity name (facts §7) and a pick.</summary>
    /// <param name="name">A fidelity name (<see cref="FidelityNames"/>).</param>
    /// <param name="pick">The pick it declares.</param>
    /// <returns>The reference in that mode.</returns>
    public static ReferenceAdapter Declaring(string name, PickPolicy pick)
    {
        Assert.True(FidelityNames.TryParse([name], out var indoor, out var outdoor, out _), name);
        return new ReferenceAdapter(pick, outdoor: outdoor) { Indoor = indoor };
    }

    /// <summary>Returns an implementation serving another's answers while declaring retail fidelity (its pick kept).</summary>
    /// <param name="inner">The implementation whose answers are served.</param>
    /// <returns>The undeclared port.</returns>
    public static ICellPhysics DeclaringRetail(ICellPhysics inner) => new DeclaresRetail(inner);

    private sealed class DeclaresRetail(ICellPhysics inner) : Forwarding(inner), ICellPhysics
    {
        public override IndoorFidelity Indoor => IndoorFidelity.Retail;

        // A whole walk answered as the inner port answers it (its stale array lives for the walk).
        public IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) => Inner.FindCellWalk(walk);

        public override OutdoorFidelity Outdoor => OutdoorFidelity.Retail;
    }
}
