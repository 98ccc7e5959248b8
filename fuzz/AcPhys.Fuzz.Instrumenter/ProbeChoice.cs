namespace AcPhys.Fuzz.Instrumenter;

/// <summary>
/// Which types of an assembly get SharpFuzz's probes: every type but value types (issue 51). The value types of the
/// suite are domain names and small records (<c>CellId</c>, <c>Lcoord</c>, <c>Sphere</c>, fidelity flags): accessors
/// without a branch worth guiding afl-fuzz, and a probe at their entry made them too big for the JIT to inline, so
/// instrumented physics paid a call per <c>CellId.Value</c> (6 % of an instrumented walk input's time alone).
/// </summary>
internal static class ProbeChoice
{
    /// <summary>Returns the matcher SharpFuzz's <c>Fuzzer.Instrument</c> takes for an assembly: true for a type to instrument.</summary>
    /// <param name="path">The assembly.</param>
    /// <returns>The matcher (by SharpFuzz's full type name, nested types as <c>Outer/Nested</c>).</returns>
    public static Func<string, bool> For(string path)
    {
        using var module = dnlib.DotNet.ModuleDefMD.Load(File.ReadAllBytes(path));
        var skipped = module.GetTypes().Where(t => t.IsValueType && !t.IsEnum).Select(t => t.FullName).ToHashSet(StringComparer.Ordinal);
        return name => !skipped.Contains(name);
    }
}
