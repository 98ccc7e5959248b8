using AcPhys.Spec.Invariants;

namespace AcPhys.Props.Meta;

/// <summary>Every catalogue invariant is labelled retail or hardening (issue #18), and the table names only catalogue IDs.</summary>
public sealed class ScopeLabelTests
{
    [Fact]
    public void Catalogue_EveryInvariantHasAScopeLabel()
    {
        var unlabelled = InvariantCatalogue.All.Where(i => i.Scope is null).Select(i => i.Id).ToArray();
        Assert.True(unlabelled.Length == 0, "unlabelled (add them to spec/Invariants/InvariantScope.cs): " + string.Join(", ", unlabelled));
    }

    [Fact]
    public void ScopeTable_NamesOnlyCatalogueIds()
    {
        var ids = InvariantCatalogue.All.Select(i => i.Id).ToHashSet();
        var stray = InvariantScope.LabelledIds.Where(id => !ids.Contains(id)).ToArray();
        Assert.True(stray.Length == 0, "labels for IDs not in the catalogue: " + string.Join(", ", stray));
    }

    [Fact]
    public void Retail_LabelsCiteAFactsSection()
    {
        Assert.All(InvariantCatalogue.All.Where(i => i.Scope == Scope.Retail), i => Assert.Contains("§", i.ScopeReason, StringComparison.Ordinal));
    }

    [Fact]
    public void NonFiniteRules_AreHardening()
    {
        Assert.Equal(Scope.Hardening, InvariantCatalogue.Find("NONFINITE-REJECTED")!.Scope);
        Assert.Equal(Scope.Hardening, InvariantCatalogue.Find("NONFINITE-SPHERE-ENDS-LOOP")!.Scope);
    }
}
