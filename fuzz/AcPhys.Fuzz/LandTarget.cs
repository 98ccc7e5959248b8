using AcPhys.Core;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;

namespace AcPhys.Fuzz;

/// <summary>
/// The <c>land</c> target: bytes → <see cref="LandCaseCodec.Decode"/> → every LandDefs invariant against the
/// reference core, or against the core with a planted fault. A broken invariant throws
/// <see cref="InvariantViolationException"/> (carrying the invariant ID), which afl-fuzz records as a crash.
/// </summary>
internal static class LandTarget
{
    /// <summary>Gets the target.</summary>
    public static FuzzTarget Target { get; } = new(
        "land",
        "LandDefs invariants (LandCaseCodec input); ACPHYS_FAULT selects a planted fault",
        Create,
        Seeds());

    private static Action<ReadOnlySpan<byte>> Create(string? fault)
    {
        ICellPhysics impl = fault is null ? ReferenceAdapter.Instance : PlantedFaults.Create(fault);
        return data =>
        {
            var landCase = LandCaseCodec.Decode(data);
            if (InvariantCatalogue.CheckLandCase(impl, landCase) is { } violation)
            {
                throw new InvariantViolationException(violation);
            }
        };
    }

    // Plain, unremarkable cases (an interior land cell, a block id, an env cell, all zeros), block bytes below 0x80 so
    // that no planted fault already fails on a seed: a find is then the fuzzer's doing, not the seeds'.
    private static Dictionary<string, byte[]> Seeds() => new()
    {
        ["interior"] = LandCaseCodec.Encode(new LandCase(new CellId(0x3A240031), 150.5f, 30.25f, new Lcoord(1000, 1000))),
        ["block-id"] = LandCaseCodec.Encode(new LandCase(new CellId(0x1234FFFF), 10f, 100f, new Lcoord(8, 16))),
        ["env-cell"] = LandCaseCodec.Encode(new LandCase(new CellId(0x7F7F0105), 96f, 96f, new Lcoord(500, 20))),
        ["zeros"] = new byte[LandCaseCodec.Length],
    };
}
