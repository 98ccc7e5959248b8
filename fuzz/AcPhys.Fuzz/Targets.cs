using AcPhys.Fuzz.Toy;

namespace AcPhys.Fuzz;

/// <summary>The targets this harness knows.</summary>
internal static class Targets
{
    // Declared before All: static fields initialize in text order.
    private static readonly Dictionary<string, byte[]> ToySeeds = new() { ["hello"] = "hello fuzz"u8.ToArray() };

    /// <summary>Gets every target, by name.</summary>
    public static IReadOnlyList<FuzzTarget> All { get; } =
    [
        LandTarget.Target,
        WalkTarget.Target,
        new("toy", "pipeline smoke test: nested magic-bytes check, crashes on the prefix \"AC!P\"", CreateToy, ToySeeds),
        new("toy-slow", "timeout smoke test: as toy, but inputs starting with 'Z' take 300 ms", CreateToySlow, ToySeeds),
    ];

    /// <summary>Finds a target by name.</summary>
    /// <param name="name">The name.</param>
    /// <returns>The target, or null.</returns>
    public static FuzzTarget? Find(string name) => All.FirstOrDefault(t => t.Name == name);

    private static Action<ReadOnlySpan<byte>> CreateToy(string? fault)
    {
        if (fault is not null)
        {
            throw new ArgumentException($"target toy has no faults (got '{fault}')", nameof(fault));
        }

        return data => MagicHeader.Parse(data);
    }

    private static Action<ReadOnlySpan<byte>> CreateToySlow(string? fault)
    {
        var parse = CreateToy(fault);
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
