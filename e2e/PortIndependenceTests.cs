using System.Reflection.Metadata;
using System.Reflection.PortableExecutable;
using AcPhys.E2E.Support;

namespace AcPhys.E2E;

/// <summary>
/// The example port is a port, not a wrapper of the reference: from AcPhys.Core it uses only the value types the
/// contract speaks (ids, lcoords, spheres, parts, the pick policy), none of core's algorithms.
/// </summary>
public sealed class PortIndependenceTests
{
    private static readonly string[] ValueTypes = ["CellId", "Lcoord", "Sphere", "Part", "PickPolicy", "IndoorFidelity", "OutdoorFidelity"];

    [Fact(DisplayName = "PORT-INDEPENDENT: the example port references no AcPhys.Core type beyond the contract's value types")]
    public void ExamplePort_UsesOnlyCoresValueTypes()
    {
        using var file = File.OpenRead(GateTestRun.ExamplePortDll);
        using var pe = new PEReader(file);
        var md = pe.GetMetadataReader();
        var core = md.AssemblyReferences.Single(h => md.GetString(md.GetAssemblyReference(h).Name) == "AcPhys.Core");
        var used = md.TypeReferences.Select(md.GetTypeReference)
            .Where(t => t.ResolutionScope.Kind == HandleKind.AssemblyReference && (AssemblyReferenceHandle)t.ResolutionScope == core)
            .Select(t => md.GetString(t.Name)).Distinct().Order().ToArray();
        Assert.NotEmpty(used);
        Assert.True(used.All(ValueTypes.Contains), "the example port uses core's " + string.Join(", ", used.Where(u => !ValueTypes.Contains(u))));
    }
}
