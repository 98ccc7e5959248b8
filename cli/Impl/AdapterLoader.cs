using AcPhys.Contract;
using AcPhys.Spec.Adapters;

namespace AcPhys.Cli.Impl;

/// <summary>
/// Loads an <see cref="ICellPhysics"/> from a .NET assembly (<c>--impl</c>) through <see cref="AdapterAssembly"/> (the
/// loader the fuzz harness uses too): its own load context, the contract assemblies from the tool. A load failure is a
/// usage error.
/// </summary>
internal static class AdapterLoader
{
    /// <summary>Loads the assembly and creates its adapter.</summary>
    /// <param name="path">The assembly path.</param>
    /// <returns>The adapter.</returns>
    /// <exception cref="UsageException">Not loadable, no adapter class, several, or none with a public parameterless constructor.</exception>
    public static ICellPhysics Load(string path)
    {
        try
        {
            return AdapterAssembly.Load(path).Create();
        }
        catch (AdapterLoadException e)
        {
            throw new UsageException(e.Message, e);
        }
    }
}
