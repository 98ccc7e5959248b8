namespace AcPhys.Spec.Adapters;

/// <summary>The operations an implementation under test may offer; names match protocol v1 (docs/protocol.md).</summary>
[Flags]
public enum Op
{
    /// <summary>No operation.</summary>
    None = 0,

    /// <summary><c>blockid_to_lcoord</c>.</summary>
    BlockIdToLcoord = 1 << 0,

    /// <summary><c>gid_to_lcoord</c>.</summary>
    GidToLcoord = 1 << 1,

    /// <summary><c>lcoord_to_gid</c>.</summary>
    LcoordToGid = 1 << 2,

    /// <summary><c>inbound_valid_cellid</c>.</summary>
    InboundValidCellId = 1 << 3,

    /// <summary><c>get_outside_lcoord</c>.</summary>
    GetOutsideLcoord = 1 << 4,

    /// <summary><c>adjust_to_outside</c>.</summary>
    AdjustToOutside = 1 << 5,

    /// <summary><c>outside_cells</c>: the sphere variant of add_all_outside_cells on open land.</summary>
    OutsideCells = 1 << 6,

    /// <summary><c>find_cell</c>: find_cell_list (open land today; scenes later).</summary>
    FindCell = 1 << 7,

    /// <summary><c>outside_cells_parts</c>: the parts / bounding-box variant (facts §3.4); an optional extension of protocol v1.</summary>
    OutsideCellsParts = 1 << 8,

    /// <summary><c>find_cell_scene</c>: find_cell_list over a scene (env cells, portals, buildings; docs/indoor.md).</summary>
    FindCellScene = 1 << 9,

    /// <summary><c>find_cell_transition</c>: find_cell_scene as a movement transition asks it (no visibility filter); an optional extension of protocol v1.</summary>
    FindCellTransition = 1 << 10,

    /// <summary>
    /// <c>load_scene</c> / <c>unload_scene</c>: a transport capability, not an operation invariants need — the scene is
    /// sent once and <c>find_cell</c> names it by <c>scene_id</c> (docs/protocol.md, "Loading a scene once").
    /// </summary>
    LoadScene = 1 << 11,

    /// <summary>
    /// <c>dat_records</c>: with <see cref="LoadScene"/>, the scene is sent as retail dat records (base64) and a manifest
    /// instead of the project's JSON (docs/protocol.md, "Scenes as dat records"); a transport capability too.
    /// </summary>
    DatRecords = 1 << 12,

    /// <summary>
    /// <c>find_cell_walk</c>: a whole walk in one request, answered with every query's answer (docs/protocol.md, "Whole
    /// walks"); a transport capability: the walk invariants need <see cref="FindCell"/> or <see cref="FindCellScene"/>.
    /// </summary>
    FindCellWalk = 1 << 13,

    /// <summary>
    /// <c>pipeline</c>: the implementation reads the next request while it answers the last, answers in request order,
    /// takes a client-chosen <c>scene_id</c> in <c>load_scene</c>, and answers depend only on the request (and the scenes
    /// loaded); the tool then streams requests without waiting for each answer (docs/protocol.md, "Pipelining"). A
    /// transport capability, not an operation.
    /// </summary>
    Pipeline = 1 << 14,

    /// <summary>Every LandDefs operation.</summary>
    LandDefs = BlockIdToLcoord | GidToLcoord | LcoordToGid | InboundValidCellId | GetOutsideLcoord | AdjustToOutside,

    /// <summary>Every operation of protocol v1 on open land (no scene).</summary>
    OpenLand = LandDefs | OutsideCells | FindCell | OutsideCellsParts,

    /// <summary>
    /// Every operation: <see cref="OpenLand"/> and scenes, all an invariant may need. <see cref="LoadScene"/>,
    /// <see cref="DatRecords"/>, <see cref="FindCellWalk"/> and <see cref="Pipeline"/> are transports, not operations, so they are not in it.
    /// </summary>
    All = OpenLand | FindCellScene | FindCellTransition,
}

/// <summary>Protocol names of <see cref="Op"/> values.</summary>
public static class OpNames
{
    private static readonly (Op Op, string Name)[] Table =
    [
        (Op.BlockIdToLcoord, "blockid_to_lcoord"),
        (Op.GidToLcoord, "gid_to_lcoord"),
        (Op.LcoordToGid, "lcoord_to_gid"),
        (Op.InboundValidCellId, "inbound_valid_cellid"),
        (Op.GetOutsideLcoord, "get_outside_lcoord"),
        (Op.AdjustToOutside, "adjust_to_outside"),
        (Op.OutsideCells, "outside_cells"),
        (Op.FindCell, "find_cell"),
        (Op.OutsideCellsParts, "outside_cells_parts"),
        (Op.FindCellScene, "find_cell_scene"),
        (Op.FindCellTransition, "find_cell_transition"),
        (Op.LoadScene, "load_scene"),
        (Op.DatRecords, "dat_records"),
        (Op.FindCellWalk, "find_cell_walk"),
        (Op.Pipeline, "pipeline"),
    ];

    /// <summary>Returns the protocol names of every flag set in <paramref name="ops"/>.</summary>
    /// <param name="ops">A set of operations.</param>
    /// <returns>The names, in protocol order.</returns>
    public static IReadOnlyList<string> Names(Op ops) => Table.Where(t => (ops & t.Op) != 0).Select(t => t.Name).ToArray();

    /// <summary>Parses protocol names into a set of operations; unknown names are returned separately.</summary>
    /// <param name="names">Names as an implementation announced them.</param>
    /// <param name="unknown">Names this version does not know.</param>
    /// <returns>The known operations.</returns>
    public static Op Parse(IEnumerable<string> names, out IReadOnlyList<string> unknown)
    {
        var ops = Op.None;
        var rest = new List<string>();
        foreach (var name in names)
        {
            var hit = Table.FirstOrDefault(t => t.Name == name);
            if (hit.Op == Op.None)
            {
                rest.Add(name);
            }
            else
            {
                ops |= hit.Op;
            }
        }

        unknown = rest;
        return ops;
    }
}
