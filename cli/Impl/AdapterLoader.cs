using System.Reflection;
using System.Runtime.Loader;
using AcPhys.Spec.Adapters;

namespace AcPhys.Cli.Impl;

/// <summary>
/// Loads an <see cref="ICellPhysics"/> from a .NET assembly (<c>--impl</c>) in its own <see cref="AssemblyLoadContext"/>:
/// the adapter's own dependencies resolve next to it (its .deps.json), while the contract assemblies (AcPhys.Contract, AcPhys.Formats, AcPhys.Spec,
/// AcPhys.Core and what they share) come from the tool, so the interface the adapter implements is the tool's.
/// </summary>
internal static class AdapterLoader
{
    private static readonly HashSet<string> Shared = new(StringComparer.OrdinalIgnoreCase) { "AcPhys.Contract", "AcPhys.Formats", "AcPhys.Spec", "AcPhys.Core", "FsCheck", "FSharp.Core" };

    /// <summary>Loads the assembly and creates its adapter.</summary>
    /// <param name="path">The assembly path.</param>
    /// <returns>The adapter.</returns>
    /// <exception cref="UsageException">Not loadable, no adapter class, several, or none with a public parameterless constructor.</exception>
    public static ICellPhysics Load(string path)
    {
        var full = Path.GetFullPath(path);
        Assembly assembly;
        try
        {
            assembly = new AdapterLoadContext(full).LoadFromAssemblyPath(full);
        }
        catch (Exception e) when (e is BadImageFormatException or FileLoadException or FileNotFoundException)
        {
            throw new UsageException($"--impl: cannot load '{path}' as a .NET assembly: {e.Message}", e);
        }

        Type[] types;
        try
        {
            types = assembly.GetExportedTypes();
        }
        catch (Exception e) when (e is ReflectionTypeLoadException or FileNotFoundException or FileLoadException)
        {
            throw new UsageException($"--impl: cannot read the types of '{path}' (a dependency is missing?): {e.Message}", e);
        }

        var candidates = types.Where(t => t is { IsClass: true, IsAbstract: false } && typeof(ICellPhysics).IsAssignableFrom(t)).ToArray();
        if (candidates.Length == 0)
        {
            string hint = types.Any(t => t.GetInterfaces().Any(i => i.FullName == typeof(ICellPhysics).FullName))
                ? " (a class implements an ICellPhysics from another AcPhys.Contract version than this tool's)"
                : string.Empty;
            throw new UsageException($"--impl: '{path}' has no public class implementing {typeof(ICellPhysics).FullName}{hint}");
        }

        if (candidates.Length > 1)
        {
            throw new UsageException($"--impl: '{path}' has several adapter classes ({string.Join(", ", candidates.Select(t => t.FullName))}); keep one public");
        }

        var type = candidates[0];
        if (type.GetConstructor(Type.EmptyTypes) is null)
        {
            throw new UsageException($"--impl: {type.FullName} needs a public parameterless constructor");
        }

        try
        {
            return (ICellPhysics)Activator.CreateInstance(type)!;
        }
        catch (TargetInvocationException e)
        {
            throw new UsageException($"--impl: the constructor of {type.FullName} threw {e.InnerException?.GetType().Name}: {e.InnerException?.Message}", e);
        }
    }

    private sealed class AdapterLoadContext(string mainPath) : AssemblyLoadContext("acphys-impl", isCollectible: false)
    {
        private readonly AssemblyDependencyResolver resolver = new(mainPath);

        protected override Assembly? Load(AssemblyName name)
        {
            if (name.Name is not null && Shared.Contains(name.Name))
            {
                return null; // the tool's copy, from the default context
            }

            return resolver.ResolveAssemblyToPath(name) is string file ? LoadFromAssemblyPath(file) : null;
        }

        protected override IntPtr LoadUnmanagedDll(string unmanagedDllName) =>
            resolver.ResolveUnmanagedDllToPath(unmanagedDllName) is string file ? LoadUnmanagedDllFromPath(file) : IntPtr.Zero;
    }
}
