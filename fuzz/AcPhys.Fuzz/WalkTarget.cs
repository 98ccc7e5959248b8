using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;

namespace AcPhys.Fuzz;

/// <summary>
/// The <c>walk</c> target: bytes → <see cref="WalkCodec.Decode"/> (a bounded, valid walk) → the walk invariants
/// (NO-BOUNDARY-FREEZE, WALK-REVERSIBLE, MAP-EDGE-WALK), against the reference or a planted fault. A violation throws
/// <see cref="InvariantViolationException"/>, which afl-fuzz records as a crash. (Per-step outdoor-query invariants
/// such as NEIGHBOUR-SYMMETRY fail on every input under some faults, which would leave AFL no passing seed.)
/// </summary>
internal static class WalkTarget
{
    /// <summary>Gets the target.</summary>
    public static FuzzTarget Target { get; } = new(
        "walk",
        "walk invariants (WalkCodec input: start, body, up to 16 steps); ACPHYS_FAULT selects a planted fault",
        Create,
        Seeds());

    private static Action<ReadOnlySpan<byte>> Create(string? fault)
    {
        ICellPhysics impl = fault is null ? ReferenceAdapter.Instance : PlantedFaults.Create(fault);
        return data =>
        {
            var walk = WalkCodec.Decode(data);
            foreach (var invariant in WalkInvariants.All)
            {
                if (invariant.IsTestable(impl) && invariant.Check(impl, walk) is { IsViolation: true } outcome)
                {
                    throw new InvariantViolationException(new Violation(invariant.Id, outcome.Message ?? "violated", walk.ToString()) { Case = walk });
                }
            }
        };
    }

    // Interior walks that no planted fault fails on: a find is the fuzzer's doing.
    private static Dictionary<string, byte[]> Seeds() => new()
    {
        ["interior-one-step"] = [0x31, 0x00, 0x24, 0x3A, 0x00, 0x40, 0x00, 0x40, 0x00, 0x08, 0x05, 0x10, 0x00],
        ["interior-two-spheres"] = [0x11, 0x00, 0x50, 0x50, 0x00, 0x60, 0x00, 0x60, 0x01, 0x08, 0x08, 0x08, 0x08, 0x05, 0x20, 0x20],
    };
}
