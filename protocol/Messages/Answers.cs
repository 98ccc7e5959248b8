using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Protocol.Messages;

/// <summary>
/// Every answer shape of protocol v1 (docs/protocol.md, "Operations"), each written once: the server's write, the
/// client's read and the pipeline's expected-line match of the same shape (issue 42).
/// </summary>
public static class Answers
{
    /// <summary>Gets <c>{"ok", "x", "y"}</c>: <c>blockid_to_lcoord</c>, <c>gid_to_lcoord</c>, <c>get_outside_lcoord</c>.</summary>
    public static Answer<(bool Ok, int X, int Y)> Lcoord { get; } = new(
        (w, l) =>
        {
            w.WriteBoolean("ok", l.Ok);
            w.WriteNumber("x", l.X);
            w.WriteNumber("y", l.Y);
        },
        a => (Wire.ReadBool(a, "ok"), Wire.ReadInt(a, "x"), Wire.ReadInt(a, "y")));

    /// <summary>Gets <c>{"ok"}</c>: <c>inbound_valid_cellid</c>, <c>unload_scene</c>.</summary>
    public static Answer<bool> Ok { get; } = new((w, ok) => w.WriteBoolean("ok", ok), a => Wire.ReadBool(a, "ok"));

    /// <summary>Gets <c>{"cell"}</c>: <c>lcoord_to_gid</c>.</summary>
    public static Answer<CellId> Cell { get; } = new((w, id) => Wire.WriteCell(w, "cell", id), a => Wire.ReadCell(a, "cell"));

    /// <summary>Gets <c>{"cells"}</c>: <c>outside_cells</c>, <c>outside_cells_parts</c>.</summary>
    public static Answer<IReadOnlyList<CellId>> Cells { get; } = new((w, cells) => Wire.WriteCells(w, "cells", cells), a => Wire.ReadCells(a, "cells"));

    /// <summary>Gets <c>{"ok", "cell", "x", "y"}</c>: <c>adjust_to_outside</c> (a NaN reads back as the one NaN the reader makes, so it has no expected line).</summary>
    public static Answer<AdjustResult> Adjust { get; } = new(
        (w, a) =>
        {
            w.WriteBoolean("ok", a.Ok);
            Wire.WriteCell(w, "cell", a.Cell);
            Wire.WriteFloat(w, "x", a.X);
            Wire.WriteFloat(w, "y", a.Y);
        },
        a => new AdjustResult(Wire.ReadBool(a, "ok"), Wire.ReadCell(a, "cell"), Wire.ReadFloat(a, "x"), Wire.ReadFloat(a, "y")),
        a => !float.IsNaN(a.X) && !float.IsNaN(a.Y));

    /// <summary>Gets <c>{"cells", "containing", "loaded"?, "hits_interior_cell"?}</c>: <c>find_cell</c> (matched without writing its line).</summary>
    public static Answer<FindCellResult> FindCell { get; } = new(Wire.WriteFindCell, Wire.ReadFindCell, Parallel, (line, r) => new LineMatch(line).FindCellObject(r).AtEnd);

    /// <summary>Gets <c>{"scene_id"}</c>: <c>load_scene</c>.</summary>
    public static Answer<string> SceneId { get; } = new((w, id) => w.WriteString("scene_id", id), a => Wire.ReadString(a, "scene_id"));

    /// <summary>Gets <c>{"error"}</c>: any request the server cannot serve.</summary>
    public static Answer<string> Error { get; } = new((w, message) => w.WriteString("error", message), a => Wire.ReadString(a, "error"));

    /// <summary>Returns <c>{"steps": [find_cell answer, ...]}</c>: <c>find_cell_walk</c>, read as exactly <paramref name="queries"/> answers.</summary>
    /// <param name="queries">How many queries the walk asked.</param>
    /// <returns>The shape.</returns>
    public static Answer<IReadOnlyList<FindCellResult>> Walk(int queries) =>
        new(WalkWire.WriteAnswer, a => WalkWire.ReadAnswer(a, queries), walk => walk.All(Parallel), (line, walk) => new LineMatch(line).Walk(walk).AtEnd);

    // A loaded not parallel to cells is refused by the reader: such an answer has no expected line.
    private static bool Parallel(FindCellResult r) => r.Loaded is null || r.Loaded.Count == r.Cells.Count;
}
