using AcPhys.Fuzz.Toy;

namespace AcPhys.Fuzz.Targets;

/// <summary>The <c>toy</c> smoke target: a nested magic-bytes check that crashes on the prefix <c>AC!P</c>.</summary>
public class ToyTarget : FuzzTarget
{
    /// <inheritdoc/>
    public override string Name => "toy";

    /// <inheritdoc/>
    public override string Description => "pipeline smoke test: nested magic-bytes check, crashes on the prefix \"AC!P\"";

    /// <inheritdoc/>
    public sealed override TargetKind Kind => TargetKind.Smoke;

    /// <inheritdoc/>
    public override IReadOnlyDictionary<string, byte[]> Seeds { get; } = new Dictionary<string, byte[]> { ["hello"] = "hello fuzz"u8.ToArray() };

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(string? fault)
    {
        NoFault(fault);
        return data => MagicHeader.Parse(data);
    }
}
