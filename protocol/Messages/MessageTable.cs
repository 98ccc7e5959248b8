using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// The queries of protocol v1 that carry no scene (docs/protocol.md, "Operations"), one row each: a new query is one
/// row here and one member of <see cref="ICellPhysics"/>. <c>find_cell</c> and <c>find_cell_walk</c> carry a scene the
/// client sends once and the server holds, so their requests are written by the client and read by the server around
/// that state; their answers are rows of <see cref="Answers"/> like every other.
/// </summary>
public static class MessageTable
{
    /// <summary>Gets <c>blockid_to_lcoord</c>.</summary>
    public static Message<CellId, (bool Ok, int X, int Y)> BlockIdToLcoord { get; } =
        new(Op.BlockIdToLcoord, WriteCell, ReadCell, Answers.Lcoord, (impl, id) => (impl.BlockIdToLcoord(id, out var l), l.X, l.Y));

    /// <summary>Gets <c>gid_to_lcoord</c>.</summary>
    public static Message<CellId, (bool Ok, int X, int Y)> GidToLcoord { get; } =
        new(Op.GidToLcoord, WriteCell, ReadCell, Answers.Lcoord, (impl, id) => (impl.GidToLcoord(id, out var l), l.X, l.Y));

    /// <summary>Gets <c>lcoord_to_gid</c>.</summary>
    public static Message<(int X, int Y), CellId> LcoordToGid { get; } = new(
        Op.LcoordToGid,
        (w, q) =>
        {
            w.WriteNumber("x", q.X);
            w.WriteNumber("y", q.Y);
        },
        r => (Wire.ReadInt(r, "x"), Wire.ReadInt(r, "y")),
        Answers.Cell,
        (impl, q) => impl.LcoordToGid(q.X, q.Y));

    /// <summary>Gets <c>inbound_valid_cellid</c>.</summary>
    public static Message<CellId, bool> InboundValidCellId { get; } =
        new(Op.InboundValidCellId, WriteCell, ReadCell, Answers.Ok, (impl, id) => impl.InboundValidCellId(id));

    /// <summary>Gets <c>get_outside_lcoord</c>.</summary>
    public static Message<(CellId Cell, float X, float Y), (bool Ok, int X, int Y)> GetOutsideLcoord { get; } =
        new(Op.GetOutsideLcoord, WritePoint, ReadPoint, Answers.Lcoord, (impl, q) => (impl.GetOutsideLcoord(q.Cell, q.X, q.Y, out var l), l.X, l.Y));

    /// <summary>Gets <c>adjust_to_outside</c>.</summary>
    public static Message<(CellId Cell, float X, float Y), AdjustResult> AdjustToOutside { get; } =
        new(Op.AdjustToOutside, WritePoint, ReadPoint, Answers.Adjust, (impl, q) => impl.AdjustToOutside(q.Cell, q.X, q.Y));

    /// <summary>Gets <c>outside_cells</c>.</summary>
    public static Message<(CellId Cell, Vector3 Origin, IReadOnlyList<Sphere> Spheres), IReadOnlyList<CellId>> OutsideCells { get; } = new(
        Op.OutsideCells,
        (w, q) =>
        {
            Wire.WriteCell(w, "cell", q.Cell);
            Wire.WriteSpheres(w, "spheres", q.Spheres);
            Wire.WriteOrigin(w, q.Origin, q.Spheres);
        },
        r => (Wire.ReadCell(r, "cell"), Wire.ReadOrigin(r), Wire.ReadSpheres(r, "spheres")),
        Answers.Cells,
        (impl, q) => impl.OutsideCells(q.Cell, q.Origin, q.Spheres));

    /// <summary>Gets <c>outside_cells_parts</c>.</summary>
    public static Message<IReadOnlyList<Part>, IReadOnlyList<CellId>> OutsideCellsParts { get; } = new(
        Op.OutsideCellsParts,
        (w, parts) => PartWire.WriteParts(w, "parts", parts),
        r => PartWire.ReadParts(r, "parts"),
        Answers.Cells,
        (impl, parts) => impl.OutsideCellsParts(parts));

    /// <summary>
    /// Gets <c>find_cell_parts_scene</c>: the parts cell list over a scene, static placement (docs/protocol.md, "Parts
    /// indoors"). The row writes and reads <c>parts</c>; the scene travels as <c>find_cell</c>'s does (<c>scene_id</c> or
    /// <c>scene</c>), written by the client and resolved by the server, which holds the loaded scenes.
    /// </summary>
    public static Message<PartsInScene, FindCellResult> FindCellPartsScene { get; } = ScenePartsRow(Op.FindCellPartsScene, false);

    /// <summary>Gets <c>find_cell_parts_transition</c>: as <see cref="FindCellPartsScene"/>, asked as a movement transition (no visibility filter).</summary>
    public static Message<PartsInScene, FindCellResult> FindCellPartsTransition { get; } = ScenePartsRow(Op.FindCellPartsTransition, true);

    /// <summary>Gets the rows by request name, as the server dispatches them.</summary>
    public static IReadOnlyDictionary<string, IServedMessage> ByName { get; } =
        new IServedMessage[] { BlockIdToLcoord, GidToLcoord, LcoordToGid, InboundValidCellId, GetOutsideLcoord, AdjustToOutside, OutsideCells, OutsideCellsParts }
            .ToDictionary(m => m.Name, StringComparer.Ordinal);

    private static Message<PartsInScene, FindCellResult> ScenePartsRow(Op op, bool loadCells) => new(
        op,
        (w, q) => PartWire.WriteParts(w, "parts", q.Parts),
        r => new PartsInScene(null, PartWire.ReadParts(r, "parts")),
        Answers.FindCell,
        (impl, q) => impl.FindCellParts(q.Scene ?? throw new InvalidOperationException("a parts query asked without its scene"), q.Parts, loadCells));

    private static void WriteCell(System.Text.Json.Utf8JsonWriter w, CellId id) => Wire.WriteCell(w, "cell", id);

    private static CellId ReadCell(System.Text.Json.JsonElement r) => Wire.ReadCell(r, "cell");

    private static void WritePoint(System.Text.Json.Utf8JsonWriter w, (CellId Cell, float X, float Y) q)
    {
        Wire.WriteCell(w, "cell", q.Cell);
        Wire.WriteFloat(w, "x", q.X);
        Wire.WriteFloat(w, "y", q.Y);
    }

    private static (CellId Cell, float X, float Y) ReadPoint(System.Text.Json.JsonElement r) => (Wire.ReadCell(r, "cell"), Wire.ReadFloat(r, "x"), Wire.ReadFloat(r, "y"));
}
