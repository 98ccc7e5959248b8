using AcPhys.Contract;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// What protocol v1 negotiates in the <c>hello</c> handshake beside the operations a port states (<see cref="Op"/>): how
/// scenes and walks travel and whether requests may be streamed. They mean nothing to an in-process port, so they are
/// not in the contract (issue 42); the engine sees them through <see cref="ITransport"/>.
/// </summary>
[Flags]
public enum Capability
{
    /// <summary>Nothing beyond the operations.</summary>
    None = 0,

    /// <summary><c>load_scene</c> / <c>unload_scene</c>: the scene is sent once and <c>find_cell</c> names it by <c>scene_id</c> (docs/protocol.md, "Loading a scene once").</summary>
    LoadScene = 1 << 0,

    /// <summary><c>dat_records</c>: with <see cref="LoadScene"/>, the scene is sent as retail dat records (base64) and a manifest instead of the project's JSON (docs/protocol.md, "Scenes as dat records").</summary>
    DatRecords = 1 << 1,

    /// <summary><c>find_cell_walk</c>: a whole walk in one request, answered with every query's answer (docs/protocol.md, "Whole walks"); the walk invariants still need <see cref="Op.FindCell"/> or <see cref="Op.FindCellScene"/>.</summary>
    FindCellWalk = 1 << 2,

    /// <summary>
    /// <c>pipeline</c>: the implementation reads the next request while it answers the last, answers in request order,
    /// takes a client-chosen <c>scene_id</c> in <c>load_scene</c>, and answers depend only on the request (and the scenes
    /// loaded); the tool then streams requests without waiting for each answer (docs/protocol.md, "Pipelining").
    /// </summary>
    Pipeline = 1 << 3,

    /// <summary>
    /// <c>find_cell_parts_walk</c>: one walk's parts queries of one kind in one request, answered with every query's answer
    /// (docs/protocol.md, "Whole parts walks"); a port declaring ace-keeps-stale-cells that offers a parts kind must
    /// announce it, since its array lives for the walk (facts §7 #6). The parts invariants still need the parts op.
    /// </summary>
    FindCellPartsWalk = 1 << 4,

    /// <summary>Every capability protocol v1 knows.</summary>
    All = LoadScene | DatRecords | FindCellWalk | Pipeline | FindCellPartsWalk,
}

/// <summary>Wire names of <see cref="Capability"/> values, announced after the operations in <c>hello</c>'s <c>ops</c>.</summary>
public static class CapabilityNames
{
    private static readonly (Capability Capability, string Name)[] Table =
    [
        (Capability.LoadScene, "load_scene"),
        (Capability.DatRecords, "dat_records"),
        (Capability.FindCellWalk, "find_cell_walk"),
        (Capability.Pipeline, "pipeline"),
        (Capability.FindCellPartsWalk, "find_cell_parts_walk"),
    ];

    /// <summary>Returns the wire names of every flag set in <paramref name="capabilities"/>.</summary>
    /// <param name="capabilities">A set of capabilities.</param>
    /// <returns>The names, in protocol order.</returns>
    public static IReadOnlyList<string> Names(Capability capabilities) => Table.Where(t => (capabilities & t.Capability) != 0).Select(t => t.Name).ToArray();

    /// <summary>Returns every name <c>hello</c>'s <c>ops</c> may hold: the operations', then the capabilities', in protocol order.</summary>
    /// <returns>The names.</returns>
    public static IReadOnlyList<string> Known() => [.. OpNames.Names(Op.All), .. Names(Capability.All)];

    /// <summary>Splits the names a <c>hello</c> announced into operations and capabilities; the rest are returned separately.</summary>
    /// <param name="names">The names, as announced.</param>
    /// <param name="capabilities">The capabilities among them.</param>
    /// <param name="unknown">Names this version knows as neither, in announced order.</param>
    /// <returns>The operations among them.</returns>
    public static Op Parse(IEnumerable<string> names, out Capability capabilities, out IReadOnlyList<string> unknown)
    {
        var ops = OpNames.Parse(names, out var notOps);
        capabilities = Capability.None;
        var rest = new List<string>();
        foreach (string name in notOps)
        {
            var hit = Table.FirstOrDefault(t => t.Name == name);
            if (hit.Capability == Capability.None)
            {
                rest.Add(name);
            }
            else
            {
                capabilities |= hit.Capability;
            }
        }

        unknown = rest;
        return ops;
    }
}
