using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// The <c>parts</c> target: bytes → <see cref="PartsCodec"/> (1–4 parts with cell, origin, rotation, box, radius and
/// Always2D, origins free in the block or on a cell or block line, parts in neighbouring block frames) → every parts
/// invariant (<see cref="InvariantCatalogue.CheckParts"/>: PARTS-COVERAGE, PARTS-SOUNDNESS). Crashes shrink with
/// <see cref="PartsGens.Shrink"/> into a <c>parts</c> regression.
/// </summary>
public sealed class PartsTarget : PhysicsTarget<PartsCase>
{
    /// <inheritdoc/>
    public override string Name => "parts";

    /// <inheritdoc/>
    public override string Description => "every parts invariant on one PartsCodec query (1–4 parts, 51 bytes)";

    // Plain queries that hold under both parts faults, so that a find is the fuzzer's doing: the zero input (one small
    // box at the map's corner), one box inside a block, one yawed Always2D part, and two parts in one cell (one anchor
    // or every part anchoring gives the same range). Near-line cases are in corpus/fuzz/parts.

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = new Dictionary<string, byte[]>
    {
        ["zeros"] = new byte[PartsCodec.Length],
        ["interior-box"] = [0x00, 0x80, 0x80, 0x00, 0x00, 0x80, 0x00, 0x80, 0x00, 0x00, 0x00, 0x00, 0x40, 0x40, 0x40],
        ["always2d-yaw"] = [0x00, 0x40, 0x20, 0x03, 0x00, 0x40, 0x00, 0x30, 0x20, 0x00, 0x00, 0x00, 0x30, 0x30, 0x30],
        ["two-parts-one-cell"] =
        [
            0x01, 0x10, 0xF0,
            0x04, 0x00, 0x22, 0x00, 0x22, 0x7F, 0x10, 0x20, 0x40, 0x20, 0x10, 0x08,
            0x00, 0x00, 0x21, 0x00, 0x23, 0x00, 0x00, 0x00, 0x00, 0x10, 0x10, 0x10,
        ],
    };

    /// <inheritdoc/>
    public override CaseKind Judged => CaseKind.Parts;

    /// <inheritdoc/>
    public override PartsCase Decode(ReadOnlySpan<byte> data) => PartsCodec.Decode(data);

    /// <inheritdoc/>
    public override Violation? Check(ICellPhysics impl, PartsCase c) => InvariantCatalogue.CheckParts(impl, c);

    /// <inheritdoc/>
    public override object Physics(PartsCase c) => ReferenceAdapter.Instance.OutsideCellsParts(c.Parts);

    /// <inheritdoc/>
    public override IEnumerable<PartsCase> Shrink(PartsCase c) => PartsGens.Shrink(c);
}
