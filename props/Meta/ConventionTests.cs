using System.Reflection;
using System.Text.RegularExpressions;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;

namespace AcPhys.Props.Meta;

/// <summary>Rules that matter, enforced by tests rather than by reviewers.</summary>
public sealed partial class ConventionTests
{
    [Fact(DisplayName = "Invariant IDs are unique, upper-case with dashes, and every statement is one sentence")]
    public void InvariantIdsAreWellFormed()
    {
        var ids = InvariantCatalogue.All.Select(i => i.Id).ToList();
        Assert.Equal(ids.Count, ids.Distinct().Count());
        Assert.All(InvariantCatalogue.All, i =>
        {
            Assert.Matches(IdPattern(), i.Id);
            Assert.EndsWith(".", i.Statement, StringComparison.Ordinal);
            Assert.False(string.IsNullOrWhiteSpace(i.Source));
        });
    }

    [Fact(DisplayName = "Every invariant has a property test whose display name starts with its ID")]
    public void EveryInvariantHasAProperty()
    {
        var names = typeof(ConventionTests).Assembly.GetTypes()
            .SelectMany(t => t.GetMethods())
            .SelectMany(m => m.GetCustomAttributes<FactAttribute>())
            .Select(a => a.DisplayName ?? string.Empty)
            .ToList();
        Assert.All(InvariantCatalogue.All, i => Assert.Contains(names, n => n.StartsWith(i.Id + ":", StringComparison.Ordinal)));
    }

    [Fact(DisplayName = "Every planted fault names catchers that exist in the catalogue")]
    public void FaultCatchersExist() =>
        Assert.All(PlantedFaults.All, f => Assert.All(f.CaughtBy, id => Assert.NotNull(InvariantCatalogue.Find(id))));

    [Fact(DisplayName = "Every public struct in core is readonly and documented value semantics (IEquatable)")]
    public void CoreStructsAreReadonly()
    {
        var structs = typeof(CellId).Assembly.GetExportedTypes().Where(t => t.IsValueType && !t.IsEnum).ToList();
        Assert.NotEmpty(structs);
        Assert.All(structs, t =>
        {
            Assert.True(t.GetCustomAttributes().Any(a => a.GetType().Name == "IsReadOnlyAttribute"), t.Name + " is not readonly");
            Assert.True(t.GetInterfaces().Any(i => i.IsGenericType && i.GetGenericTypeDefinition() == typeof(IEquatable<>)), t.Name + " lacks IEquatable");
        });
    }

    [Fact(DisplayName = "Core references nothing but the base class library")]
    public void CoreHasNoPackageDependencies()
    {
        var refs = typeof(CellId).Assembly.GetReferencedAssemblies().Select(a => a.Name!).ToList();
        Assert.All(refs, name => Assert.True(name.StartsWith("System", StringComparison.Ordinal) || name == "netstandard", name));
    }

    [Fact(DisplayName = "docs/invariants.md is exactly the catalogue (regenerate: ./acphys invariants --markdown > docs/invariants.md)")]
    public void InvariantDocsAreCurrent()
    {
        string path = Path.Combine(RepoPaths.Root, "docs", "invariants.md");
        Assert.True(File.Exists(path), path + " missing");
        Assert.Equal(InvariantDocs.Markdown(), File.ReadAllText(path));
    }

    [GeneratedRegex("^[A-Z][A-Z0-9]*(-[A-Z0-9]+)*$")]
    private static partial Regex IdPattern();
}
