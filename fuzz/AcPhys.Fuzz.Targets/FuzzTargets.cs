namespace AcPhys.Fuzz.Targets;

/// <summary>The registry: every concrete <see cref="FuzzTarget"/> in this assembly, by name.</summary>
public static class FuzzTargets
{
    /// <summary>Gets every target, ordered by kind, then name.</summary>
    public static IReadOnlyList<FuzzTarget> All { get; } = typeof(FuzzTarget).Assembly.GetTypes()
        .Where(t => t.IsSubclassOf(typeof(FuzzTarget)) && !t.IsAbstract && t.GetConstructor(Type.EmptyTypes) is not null)
        .Select(t => (FuzzTarget)Activator.CreateInstance(t)!)
        .OrderBy(t => t.Kind)
        .ThenBy(t => t.Name, StringComparer.Ordinal)
        .ToArray();

    /// <summary>Finds a target by name.</summary>
    /// <param name="name">The name.</param>
    /// <returns>The target, or null.</returns>
    public static FuzzTarget? Find(string? name) => All.FirstOrDefault(t => t.Name == name);
}
