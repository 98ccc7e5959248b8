using System.Reflection;
using System.Runtime.Loader;

namespace AcPhys.Fuzz.Tests;

/// <summary>
/// Loads instrumented copies from a directory next to their originals, while SharpFuzz.Common (and anything
/// not in the directory) comes from the default context, so that probes write into the same <c>Trace.SharedMem</c> map.
/// </summary>
internal sealed class IsolatedContext(string directory) : AssemblyLoadContext(isCollectible: true)
{
    protected override Assembly? Load(AssemblyName assemblyName)
    {
        string candidate = Path.Combine(directory, assemblyName.Name + ".dll");
        return assemblyName.Name != "SharpFuzz.Common" && File.Exists(candidate) ? LoadFromAssemblyPath(candidate) : null;
    }
}
