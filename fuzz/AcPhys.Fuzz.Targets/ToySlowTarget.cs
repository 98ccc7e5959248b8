namespace AcPhys.Fuzz.Targets;

/// <summary>The <c>toy-slow</c> smoke target: as <c>toy</c>, but inputs starting with <c>Z</c> take 300 ms (a timeout test).</summary>
public sealed class ToySlowTarget : ToyTarget
{
    /// <inheritdoc/>
    public override string Name => "toy-slow";

    /// <inheritdoc/>
    public override bool MayHang => true;

    /// <inheritdoc/>
    public override string Description => "timeout smoke test: as toy, but inputs starting with 'Z' take 300 ms";

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(string? fault)
    {
        var parse = base.CreateTest(fault);
        return data =>
        {
            if (!data.IsEmpty && data[0] == (byte)'Z')
            {
                Thread.Sleep(300);
            }

            parse(data);
        };
    }
}
