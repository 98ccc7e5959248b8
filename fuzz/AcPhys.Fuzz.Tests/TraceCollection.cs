using Xunit;

namespace AcPhys.Fuzz.Tests;

/// <summary>Tests that use the process-wide coverage map run one at a time.</summary>
[CollectionDefinition(Name, DisableParallelization = true)]
public sealed class TraceCollection
{
    /// <summary>The collection name.</summary>
    public const string Name = "coverage map";
}
