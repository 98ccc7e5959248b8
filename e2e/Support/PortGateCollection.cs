namespace AcPhys.E2E.Support;

/// <summary>The tests that build or run the example port's gate tests, one at a time (they share its output folder).</summary>
[CollectionDefinition(Name)]
public sealed class PortGateCollection
{
    /// <summary>The collection's name.</summary>
    public const string Name = "example port gate";
}
