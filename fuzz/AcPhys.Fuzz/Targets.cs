using AcPhys.Fuzz.Toy;

namespace AcPhys.Fuzz;

/// <summary>The targets this harness knows.</summary>
internal static class Targets
{
    /// <summary>Gets every target, by name.</summary>
    public static IReadOnlyList<FuzzTarget> All { get; } =
    [
        new("toy", "pipeline smoke test: nested magic-bytes check, crashes on the prefix \"AC!P\"", CreateToy),
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
}
