using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>walk</c> target: bytes → <see cref="WalkCodec"/> (a bounded walk: land start, 1–3 spheres, up to 16 steps)
/// → <see cref="InvariantCatalogue.CheckWalk"/>: the walk invariants, then every outdoor invariant on each step's query.
/// </summary>
public sealed class WalkTarget : PhysicsTarget<Walk>
{
    /// <inheritdoc/>
    public override string Name => "walk";

    /// <inheritdoc/>
    public override string Description => "walk invariants + every outdoor invariant per step (WalkCodec: start, body, up to 16 steps)";

    // Interior walks; "interior-point" (one sphere of radius 0, no steps) passes under every planted fault that does
    // not fail on every query, so afl-fuzz has a passing seed to mutate.

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = new Dictionary<string, byte[]>
    {
        ["interior-point"] = [0x31, 0x00, 0x24, 0x3A, 0x00, 0x40, 0x00, 0x40, 0x00, 0x00],
        ["interior-one-step"] = [0x31, 0x00, 0x24, 0x3A, 0x00, 0x40, 0x00, 0x40, 0x00, 0x08, 0x05, 0x10, 0x00],
        ["interior-two-spheres"] = [0x11, 0x00, 0x50, 0x50, 0x00, 0x60, 0x00, 0x60, 0x01, 0x08, 0x08, 0x08, 0x08, 0x05, 0x20, 0x20],
    };

    /// <inheritdoc/>
    public override CaseKind Judged => CaseKind.Walk;

    /// <inheritdoc/>
    public override Walk Decode(ReadOnlySpan<byte> data) => WalkCodec.Decode(data);

    /// <inheritdoc/>
    public override Violation? Check(ICellPhysics impl, Walk c) => InvariantCatalogue.CheckWalk(impl, c);

    /// <inheritdoc/>
    public override object Physics(Walk c) => ReferenceAdapter.Instance.FindCellWalk(WalkRunner.Request(c, null));

    /// <inheritdoc/>
    public override IEnumerable<Walk> Shrink(Walk c) => WalkShrinker.Shrink(c);
}
