namespace ExamplePort;

/// <summary>
/// The port's seeded bugs, switched by <c>ACPHYS_PORT_BUG</c>: each is a mistake a port of this area has made or
/// could make, and each must be caught by the gate (e2e/PortGateTests.cs).
/// </summary>
public enum Bug
{
    /// <summary>No bug: the port as written.</summary>
    None,

    /// <summary><c>clamp-106</c>: neighbour candidates clamped to the sphere's own landblock (issue #106, facts §3.3: the grid is global).</summary>
    Clamp106,

    /// <summary><c>trunc</c>: the 24 m column by truncation toward zero instead of floor (facts §2, get_outside_lcoord).</summary>
    Trunc,

    /// <summary><c>edge-off-by-one</c>: the map's far edge taken as inclusive, lcoord 2040 on the map (facts §1.3).</summary>
    EdgeOffByOne,

    /// <summary><c>inbound-x-only</c>: inbound_valid_cellid tests only the x byte (ACE's, facts §2 and §7).</summary>
    InboundXOnly,

    /// <summary><c>hang</c>: inbound_valid_cellid never returns for one id (<see cref="Bugs.HangCell"/>), as a port's endless loop would: a finding of its own kind for <c>acphys fuzz --impl</c> (HANG), not an invariant's.</summary>
    Hang,
}

/// <summary>Reads <c>ACPHYS_PORT_BUG</c>.</summary>
public static class Bugs
{
    /// <summary>Gets the bug names as <c>ACPHYS_PORT_BUG</c> takes them.</summary>
    public static IReadOnlyDictionary<string, Bug> Names { get; } = new Dictionary<string, Bug>
    {
        ["clamp-106"] = Bug.Clamp106,
        ["trunc"] = Bug.Trunc,
        ["edge-off-by-one"] = Bug.EdgeOffByOne,
        ["inbound-x-only"] = Bug.InboundXOnly,
        ["hang"] = Bug.Hang,
    };

    /// <summary>The id <see cref="Bug.Hang"/> never returns for: an env cell no seed of the land target holds.</summary>
    public const uint HangCell = 0x4A2BAC01;

    /// <summary>Never returns (sleeping, so a hang costs no CPU).</summary>
    /// <returns>Nothing: it never returns.</returns>
    public static bool Forever()
    {
        while (true)
        {
            Thread.Sleep(100);
        }
    }

    /// <summary>Returns the bug the environment switches on.</summary>
    /// <returns>The bug, <see cref="Bug.None"/> when unset.</returns>
    /// <exception cref="InvalidOperationException">An unknown name.</exception>
    public static Bug FromEnvironment() => Environment.GetEnvironmentVariable("ACPHYS_PORT_BUG") is not { Length: > 0 } name ? Bug.None
        : Names.TryGetValue(name, out var bug) ? bug
        : throw new InvalidOperationException($"ACPHYS_PORT_BUG='{name}' is not a bug of this port (known: {string.Join(", ", Names.Keys)})");
}
