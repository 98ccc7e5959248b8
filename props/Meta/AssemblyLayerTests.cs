using System.Xml.Linq;
using AcPhys.Props.Support;

namespace AcPhys.Props.Meta;

/// <summary>
/// The assemblies by job, dependencies one way (docs/architecture.md): core ← contract ← formats ← protocol, and
/// formats ← checking beside it (the engine never references the protocol: issue 42), the numerics studies above the
/// engine and referenced by none of it. Pinned twice: what each compiled assembly
/// references, and what its project file declares (a package reference a NuGet consumer would inherit even unused).
/// </summary>
public sealed class AssemblyLayerTests
{
    /// <summary>The layers, lowest first: assembly, project file, the packages it may use.</summary>
    private static readonly (string Assembly, string Project, string[] Packages)[] Layers =
    [
        ("AcPhys.Core", "core/AcPhys.Core.csproj", []),
        ("AcPhys.Contract", "contract/AcPhys.Contract.csproj", []),
        ("AcPhys.Formats", "formats/AcPhys.Formats.csproj", []),
        ("AcPhys.Protocol", "protocol/AcPhys.Protocol.csproj", []),
        ("AcPhys.Spec", "spec/AcPhys.Spec.csproj", ["FsCheck", "FSharp.Core"]),
        ("AcPhys.Studies", "studies/AcPhys.Studies.csproj", ["FsCheck", "FSharp.Core"]),
    ];

    public static TheoryData<string> LayerNames => [.. Layers.Select(l => l.Assembly)];

    [Theory(DisplayName = "LAYERS-ASSEMBLY: a compiled assembly references only the BCL, the layers below it and its own packages")]
    [MemberData(nameof(LayerNames))]
    public void Assembly_ReferencesOnlyLowerLayersAndItsPackages(string name)
    {
        var (allowedLayers, packages) = Allowed(name);
        var refs = System.Reflection.Assembly.Load(name).GetReferencedAssemblies().Select(a => a.Name!).ToArray();
        var stray = refs.Where(r => !IsBcl(r) && !allowedLayers.Contains(r) && !packages.Contains(r)).ToArray();
        Assert.True(stray.Length == 0, $"{name} references {string.Join(", ", stray)}; it may reference the BCL, {Describe(allowedLayers, packages)}");
    }

    [Theory(DisplayName = "LAYERS-PROJECT: a layer's project file declares project references to lower layers only and no package beyond its own")]
    [MemberData(nameof(LayerNames))]
    public void Project_DeclaresOnlyLowerLayersAndItsPackages(string name)
    {
        var (allowedLayers, packages) = Allowed(name);
        var layer = Layers.Single(l => l.Assembly == name);
        var project = XDocument.Load(Path.Combine(RepoPaths.Root, layer.Project));
        var projectRefs = project.Descendants("ProjectReference").Select(e => Path.GetFileNameWithoutExtension((string)e.Attribute("Include")!)).ToArray();
        var packageRefs = project.Descendants("PackageReference").Select(e => (string)e.Attribute("Include")!).ToArray();
        var stray = projectRefs.Where(p => !allowedLayers.Contains(p)).Concat(packageRefs.Where(p => !packages.Contains(p))).ToArray();
        Assert.True(stray.Length == 0, $"{layer.Project} declares {string.Join(", ", stray)}; it may declare {Describe(allowedLayers, packages)}");
    }

    [Fact(DisplayName = "LAYERS-CONTRACT: the contract a port implements references AcPhys.Core and the BCL only, so a .NET port pulls in no FsCheck")]
    public void Contract_ReferencesCoreAndTheBclOnly()
    {
        var refs = System.Reflection.Assembly.Load("AcPhys.Contract").GetReferencedAssemblies().Select(a => a.Name!).Where(r => !IsBcl(r));
        Assert.Equal(["AcPhys.Core"], refs.ToArray());
    }

    [Fact(DisplayName = "LAYERS-STUDIES: no layer below the numerics studies references them (the checking engine runs without them)")]
    public void Studies_AreReferencedByNoLowerLayer()
    {
        var users = Layers.Where(l => l.Assembly != "AcPhys.Studies")
            .Where(l => System.Reflection.Assembly.Load(l.Assembly).GetReferencedAssemblies().Any(a => a.Name == "AcPhys.Studies"))
            .Select(l => l.Assembly).ToArray();
        Assert.True(users.Length == 0, "AcPhys.Studies is referenced by " + string.Join(", ", users));
    }

    [Theory(DisplayName = "LAYERS-PROTOCOL: the checking engine does not reference AcPhys.Protocol, compiled or declared: it asks contract's ITransport, never a transport class")]
    [InlineData("AcPhys.Spec", "spec/AcPhys.Spec.csproj")]
    [InlineData("AcPhys.Studies", "studies/AcPhys.Studies.csproj")]
    public void Engine_DoesNotReferenceProtocol(string name, string projectFile)
    {
        var refs = System.Reflection.Assembly.Load(name).GetReferencedAssemblies().Select(a => a.Name!).ToArray();
        Assert.DoesNotContain("AcPhys.Protocol", refs);
        var project = XDocument.Load(Path.Combine(RepoPaths.Root, projectFile));
        var projectRefs = project.Descendants("ProjectReference").Select(e => Path.GetFileNameWithoutExtension((string)e.Attribute("Include")!)).ToArray();
        Assert.DoesNotContain("AcPhys.Protocol", projectRefs);
    }

    [Fact(DisplayName = "LAYERS-PROTOCOL: AcPhys.Formats holds no process runtime (no kill, poll, fcntl or setsid P/Invoke: those are AcPhys.Protocol's) and no protocol namespace")]
    public void Formats_HoldsNoProcessRuntime()
    {
        var formats = System.Reflection.Assembly.Load("AcPhys.Formats");
        Assert.Empty(ProcessCalls(formats));
        Assert.Empty(formats.GetTypes().Where(t => t.Namespace?.EndsWith(".Protocol", StringComparison.Ordinal) == true).Select(t => t.FullName));
        Assert.NotEmpty(ProcessCalls(System.Reflection.Assembly.Load("AcPhys.Protocol"))); // the check can fail: the runtime is there
    }

    // The native process-management entry points an assembly imports (a stat of a file is not one).
    private static string[] ProcessCalls(System.Reflection.Assembly assembly)
    {
        const System.Reflection.BindingFlags All = System.Reflection.BindingFlags.Public | System.Reflection.BindingFlags.NonPublic | System.Reflection.BindingFlags.Static | System.Reflection.BindingFlags.Instance | System.Reflection.BindingFlags.DeclaredOnly;
        string[] process = ["kill", "poll", "fcntl", "setsid", "setpgid", "waitpid"];
        return [.. assembly.GetTypes().SelectMany(t => t.GetMethods(All))
            .Select(m => (Method: m, Import: System.Reflection.CustomAttributeExtensions.GetCustomAttribute<System.Runtime.InteropServices.DllImportAttribute>(m)))
            .Where(p => p.Import is { } i && process.Contains(i.EntryPoint ?? p.Method.Name))
            .Select(p => p.Method.DeclaringType!.Name + "." + p.Method.Name)];
    }

    private static (HashSet<string> Layers, HashSet<string> Packages) Allowed(string name)
    {
        int index = Array.FindIndex(Layers, l => l.Assembly == name);
        Assert.True(index >= 0, name + " is not a layer");
        return ([.. Layers.Take(index).Select(l => l.Assembly)], [.. Layers[index].Packages]);
    }

    /// <summary>Whether an assembly is the BCL: it loads from the shared framework's folder (System.*, Microsoft.Win32.*, netstandard).</summary>
    private static bool IsBcl(string name) =>
        System.Reflection.Assembly.Load(name).Location.StartsWith(System.Runtime.InteropServices.RuntimeEnvironment.GetRuntimeDirectory(), StringComparison.Ordinal);

    private static string Describe(HashSet<string> layers, HashSet<string> packages) =>
        $"layers [{string.Join(", ", layers)}], packages [{string.Join(", ", packages)}]";
}
