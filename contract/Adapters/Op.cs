namespace AcPhys.Contract;

/// <summary>The operations an implementation under test may offer (physics only; a transport negotiates the rest, <see cref="ITransport"/>); names match protocol v1 (docs/protocol.md).</summary>
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

    /// <summary><c>find_cell_parts_scene</c>: the parts / bounding-box cell list over a scene as static placement (visibility filter on; facts §5.2, §5.3); an optional extension of protocol v1.</summary>
    FindCellPartsScene = 1 << 11,

    /// <summary><c>find_cell_parts_transition</c>: the parts cell list over a scene as a movement transition asks it (no visibility filter); an optional extension of protocol v1.</summary>
    FindCellPartsTransition = 1 << 12,

    /// <summary>Every LandDefs operation.</summary>
    LandDefs = BlockIdToLcoord | GidToLcoord | LcoordToGid | InboundValidCellId | GetOutsideLcoord | AdjustToOutside,

    /// <summary>Every operation of protocol v1 on open land (no scene).</summary>
    OpenLand = LandDefs | OutsideCells | FindCell | OutsideCellsParts,

    /// <summary>
    /// Every operation: <see cref="OpenLand"/> and scenes, all an invariant may need. How scenes and walks travel
    /// (<c>load_scene</c>, <c>dat_records</c>, <c>find_cell_walk</c>, <c>pipeline</c>) is not an operation: protocol v1
    /// negotiates it (<see cref="ITransport"/>; AcPhys.Protocol's <c>Capability</c>).
    /// </summary>
    All = OpenLand | FindCellScene | FindCellTransition | FindCellPartsScene | FindCellPartsTransition,
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
        (Op.FindCellPartsScene, "find_cell_parts_scene"),
        (Op.FindCellPartsTransition, "find_cell_parts_transition"),
    ];

    /// <summary>Returns the protocol name of one operation.</summary>
    /// <param name="op">Exactly one operation flag.</param>
    /// <returns>Its name in protocol v1 (docs/protocol.md).</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="op"/> is not exactly one operation.</exception>
    public static string Name(Op op)
    {
        foreach (var (flag, name) in Table)
        {
            if (flag == op)
            {
                return name;
            }
        }

        throw new ArgumentOutOfRangeException(nameof(op), op, "not exactly one operation");
    }

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
