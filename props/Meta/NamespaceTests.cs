using System.Reflection;
using System.Text.RegularExpressions;
using System.Xml.Linq;
using AcPhys.Props.Support;

namespace AcPhys.Props.Meta;

/// <summary>
/// Issue 42: a namespace is its package. Every type's namespace is its assembly's root namespace or a sub-namespace of
/// it, so a port that references AcPhys.Contract writes <c>using AcPhys.Contract;</c> and no namespace is split across
/// assemblies. The root is the assembly name, or the project file's name where the assembly name is not a namespace
/// (cli: the <c>acphys</c> command, namespace AcPhys.Cli).
/// </summary>
public sealed partial class NamespaceTests
{
    [Fact(DisplayName = "NAMESPACE-IS-ASSEMBLY: every C# file of every project declares its project's root namespace or one under it")]
    public void EverySourceFileIsInItsProjectsNamespace()
    {
        var projects = Directory.EnumerateFiles(RepoPaths.Root, "*.csproj", SearchOption.AllDirectories)
            .Where(p => !IsBuildOutput(p))
            .Select(p => (Dir: Path.GetDirectoryName(p)!, Root: RootOf(p)))
            .OrderByDescending(p => p.Dir.Length)
            .ToArray();
        Assert.True(projects.Length >= 15, $"found {projects.Length} projects under {RepoPaths.Root}");
        var stray = new List<string>();
        int files = 0;
        foreach (var file in Directory.EnumerateFiles(RepoPaths.Root, "*.cs", SearchOption.AllDirectories).Where(f => !IsBuildOutput(f)))
        {
            var owner = projects.FirstOrDefault(p => file.StartsWith(p.Dir + Path.DirectorySeparatorChar, StringComparison.Ordinal));
            if (owner.Dir is null || NamespaceDeclaration().Match(File.ReadAllText(file)) is not { Success: true } m)
            {
                continue;
            }

            files++;
            string ns = m.Groups[1].Value;
            if (ns != owner.Root && !ns.StartsWith(owner.Root + ".", StringComparison.Ordinal))
            {
                stray.Add($"{Path.GetRelativePath(RepoPaths.Root, file)}: namespace {ns}, project root {owner.Root}");
            }
        }

        Assert.True(files > 400, $"only {files} C# files with a namespace found");
        Assert.True(stray.Count == 0, string.Join(Environment.NewLine, stray));
    }

    [Theory(DisplayName = "NAMESPACE-IS-ASSEMBLY-COMPILED: every type a layer assembly defines is in the assembly's namespace or under it")]
    [InlineData("AcPhys.Core")]
    [InlineData("AcPhys.Contract")]
    [InlineData("AcPhys.Formats")]
    [InlineData("AcPhys.Spec")]
    [InlineData("AcPhys.Studies")]
    public void EveryCompiledTypeIsInItsAssemblysNamespace(string assembly)
    {
        var types = Assembly.Load(assembly).GetTypes()
            .Where(t => t.Namespace is not null && !t.Namespace.StartsWith("System.", StringComparison.Ordinal) && !t.Namespace.StartsWith("Microsoft.", StringComparison.Ordinal))
            .ToArray();
        Assert.NotEmpty(types);
        var stray = types.Where(t => t.Namespace != assembly && !t.Namespace!.StartsWith(assembly + ".", StringComparison.Ordinal)).Select(t => t.FullName).ToArray();
        Assert.True(stray.Length == 0, $"{assembly} defines {string.Join(", ", stray)}");
    }

    private static string RootOf(string project)
    {
        string? name = XDocument.Load(project).Descendants("AssemblyName").Select(e => e.Value.Trim()).FirstOrDefault();
        string file = Path.GetFileNameWithoutExtension(project);
        return name is not null && NamespaceShaped().IsMatch(name) ? name : file;
    }

    private static bool IsBuildOutput(string path) =>
        path.Split(Path.DirectorySeparatorChar).Any(s => s is "obj" or "bin" or ".git" or "artifacts");

    [GeneratedRegex(@"^namespace\s+([A-Za-z_][\w.]*)\s*;", RegexOptions.Multiline)]
    private static partial Regex NamespaceDeclaration();

    [GeneratedRegex(@"^[A-Z][A-Za-z0-9]*(\.[A-Z][A-Za-z0-9]*)*$")]
    private static partial Regex NamespaceShaped();
}
