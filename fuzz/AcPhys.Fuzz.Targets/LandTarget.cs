using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;

namespace AcPhys.Fuzz.Targets;

/// <summary>The <c>land</c> target: bytes → <see cref="LandCaseCodec"/> → every LandDefs invariant (<see cref="InvariantCatalogue.CheckLandCase"/>).</summary>
public sealed class LandTarget : PhysicsTarget<LandCase>
{
    /// <inheritdoc/>
    public override string Name => "land";

    /// <inheritdoc/>
    public override string Description => "every LandDefs invariant on one LandCaseCodec case (17 bytes)";

    // Plain cases (an interior land cell, a block id, an env cell, all zeros), block bytes below 0x80 so that no
    // planted fault already fails on a seed: a find is then the fuzzer's doing, not the seeds'.

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = new Dictionary<string, byte[]>
    {
        ["interior"] = LandCaseCodec.Encode(new LandCase(new CellId(0x3A240031), 150.5f, 30.25f, new Lcoord(1000, 1000))),
        ["block-id"] = LandCaseCodec.Encode(new LandCase(new CellId(0x1234FFFF), 10f, 100f, new Lcoord(8, 16))),
        ["env-cell"] = LandCaseCodec.Encode(new LandCase(new CellId(0x7F7F0105), 96f, 96f, new Lcoord(500, 20))),
        ["zeros"] = new byte[LandCaseCodec.Length],
    };

    /// <inheritdoc/>
    public override CaseKind Judged => CaseKind.Land;

    /// <inheritdoc/>
    public override LandCase Decode(ReadOnlySpan<byte> data) => LandCaseCodec.Decode(data);

    /// <inheritdoc/>
    public override Violation? Check(ICellPhysics impl, LandCase c) => InvariantCatalogue.CheckLandCase(impl, c);

    /// <inheritdoc/>
    public override object Physics(LandCase c)
    {
        var impl = ReferenceAdapter.Instance;
        bool inside = impl.GetOutsideLcoord(c.Cell, c.X, c.Y, out var lcoord);
        return (inside, lcoord, impl.AdjustToOutside(c.Cell, c.X, c.Y), impl.LcoordToGid(c.Lcoord.X, c.Lcoord.Y));
    }

    /// <inheritdoc/>
    public override IEnumerable<LandCase> Shrink(LandCase c) => LandCaseShrinker.Shrink(c);
}
