using System.Reflection;
using System.Runtime.Loader;
using AcPhys.Contract;

namespace AcPhys.Spec.Adapters;

/// <summary>
/// A port's in-process adapter (<c>--impl PATH.dll</c>): the assembly loaded in its own <see cref="AssemblyLoadContext"/>
/// and its one public <see cref="ICellPhysics"/> class. The adapter's own dependencies resolve next to it (its
/// .deps.json), while the contract assemblies (AcPhys.Contract, AcPhys.Formats, AcPhys.Spec, AcPhys.Core, what they
/// share, and SharpFuzz's trace map when the copy is instrumented) come from the host, so the interface the adapter
/// implements is the host's. Used by <c>acphys verify/replay --impl</c> and by the fuzz harness (<c>acphys fuzz --impl</c>).
/// </summary>
public sealed class AdapterAssembly
{
    private static readonly HashSet<string> Shared = new(StringComparer.OrdinalIgnoreCase)
    {
        "AcPhys.Contract", "AcPhys.Formats", "AcPhys.Spec", "AcPhys.Core", "FsCheck", "FSharp.Core", "SharpFuzz", "SharpFuzz.Common",
    };

    private readonly Type type;

    private AdapterAssembly(string path, Type type)
    {
        Path = path;
        this.type = type;
    }

    /// <summary>Gets the assembly's full path.</summary>
    public string Path { get; }

    /// <summary>Gets the adapter class's full name.</summary>
    public string TypeName => type.FullName ?? type.Name;

    /// <summary>Loads the assembly and finds its adapter class (not yet constructed).</summary>
    /// <param name="path">The assembly path.</param>
    /// <returns>The loaded adapter assembly.</returns>
    /// <exception cref="AdapterLoadException">Not loadable, no adapter class, several, or none with a public parameterless constructor.</exception>
    public static AdapterAssembly Load(string path)
    {
        ArgumentNullException.ThrowIfNull(path);
        var full = System.IO.Path.GetFullPath(path);
        Assembly assembly;
        try
        {
            assembly = new AdapterLoadContext(full).LoadFromAssemblyPath(full);
        }
        catch (Exception e) when (e is BadImageFormatException or FileLoadException or FileNotFoundException)
        {
            throw new AdapterLoadException($"--impl: cannot load '{path}' as a .NET assembly: {e.Message}", e);
        }

        Type[] types;
        try
        {
            types = assembly.GetExportedTypes();
        }
        catch (Exception e) when (e is ReflectionTypeLoadException or FileNotFoundException or FileLoadException)
        {
            throw new AdapterLoadException($"--impl: cannot read the types of '{path}' (a dependency is missing?): {e.Message}", e);
        }

        var candidates = types.Where(t => t is { IsClass: true, IsAbstract: false } && typeof(ICellPhysics).IsAssignableFrom(t)).ToArray();
        if (candidates.Length == 0)
        {
            string hint = types.Any(t => t.GetInterfaces().Any(i => i.FullName == typeof(ICellPhysics).FullName))
                ? " (a class implements an ICellPhysics from another AcPhys.Contract version than this tool's)"
                : string.Empty;
            throw new AdapterLoadException($"--impl: '{path}' has no public class implementing {typeof(ICellPhysics).FullName}{hint}");
        }

        if (candidates.Length > 1)
        {
            throw new AdapterLoadException($"--impl: '{path}' has several adapter classes ({string.Join(", ", candidates.Select(t => t.FullName))}); keep one public");
        }

        var type = candidates[0];
        return type.GetConstructor(Type.EmptyTypes) is null
            ? throw new AdapterLoadException($"--impl: {type.FullName} needs a public parameterless constructor")
            : new AdapterAssembly(full, type);
    }

    /// <summary>Constructs a new adapter instance.</summary>
    /// <returns>The adapter.</returns>
    /// <exception cref="AdapterLoadException">Its constructor threw.</exception>
    public ICellPhysics Create()
    {
        try
        {
            return (ICellPhysics)Activator.CreateInstance(type)!;
        }
        catch (TargetInvocationException e)
        {
            throw new AdapterLoadException($"--impl: the constructor of {type.FullName} threw {e.InnerException?.GetType().Name}: {e.InnerException?.Message}", e);
        }
    }

    private sealed class AdapterLoadContext(string mainPath) : AssemblyLoadContext("acphys-impl", isCollectible: false)
    {
        private readonly AssemblyDependencyResolver resolver = new(mainPath);

        protected override Assembly? Load(AssemblyName name)
        {
            if (name.Name is not null && Shared.Contains(name.Name))
            {
                return null; // the host's copy, from the default context
            }

            return resolver.ResolveAssemblyToPath(name) is string file ? LoadFromAssemblyPath(file) : null;
        }

        protected override IntPtr LoadUnmanagedDll(string unmanagedDllName) =>
            resolver.ResolveUnmanagedDllToPath(unmanagedDllName) is string file ? LoadUnmanagedDllFromPath(file) : IntPtr.Zero;
    }
}
