using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// Planted faults of how a port reads a parts object indoors (issue 53, item 2): Always2D parts, and parts held in
/// another env cell than the anchor's. Each misreads the parts (<see cref="PartsMisread"/>) and then answers as the
/// reference, so the defect is the reading alone. The parts a scene walk stands for (spec/Cases/PartShapes.Always2D,
/// PartCells) reach them: the classes <c>parts:always2d-outside</c>, <c>parts:held-other-block-cell</c>.
/// </summary>
internal static class PartsObjectFaults
{
    /// <summary>Always2D ignored from an indoor anchor.</summary>
    public static readonly PlantedFault Always2DIgnoredIndoors = new(
        "parts-always2d-ignored-indoors",
        "from an indoor anchor, Always2D parts are taken as boxes: the land cells an exit portal adds cover each part's box, not its square ±r",
        "facts §3.4: the parts add_all_outside_cells takes an Always2D part's square [x − r, x + r]² around its raw origin; a port that wrote the Always2D path only for its outdoor entry point, and runs a box-only copy from EnvCell.find_transit_cells (§5.2), lists other land cells when an object leaves a building.",
        ["PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Every part framed in the anchor's cell from an indoor anchor.</summary>
    public static readonly PlantedFault OwnCellFrame = new(
        "parts-own-cell-frame",
        "from an indoor anchor, every part is framed in the anchor's cell instead of its own cell: a part held in another block (a land cell across the line, or another block's env cell) is read in the anchor's block",
        "facts §3.4, §5.2, §5.8: each part's Position names its own cell, and LocalToLocal applies GetBlockOffset(cell, part's cell); a port that holds an indoor object by its anchor's cell (the object's cell) puts a part held in the next block 192 m away.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>The block offset dropped for a part held in another block's env cell.</summary>
    public static readonly PlantedFault EnvBlockOffsetDropped = new(
        "parts-env-block-offset-dropped",
        "a part held in an env cell of another block than the anchor's has no block offset applied: its origin is read as if in the anchor's block",
        "facts §5.8, §3.4: GetBlockOffset is applied whatever the cells are; a port that reasons \"an env cell never crosses a block line\" and skips the offset for indoor Positions misplaces a part held in a neighbouring block's building by 192 m.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Gets every fault of this family.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [Always2DIgnoredIndoors, OwnCellFrame, EnvBlockOffsetDropped];

    /// <summary>Returns an adapter carrying a fault of this family, or null for another fault.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The adapter, or null.</returns>
    public static ICellPhysics? Create(PlantedFault fault) => All.Contains(fault) ? new PartsMisreadPhysics(fault) : null;

    /// <summary>Returns a part as a port with a fault of this family reads it (unchanged for another fault).</summary>
    /// <param name="parts">The parts as asked (the first is the anchor).</param>
    /// <param name="p">The part.</param>
    /// <param name="fault">The fault.</param>
    /// <returns>The part read.</returns>
    public static Part Misread(IReadOnlyList<Part> parts, Part p, PlantedFault fault)
    {
        var anchor = parts[0].Cell;
        bool indoor = anchor.IsIndoorByLowWord;
        bool otherBlock = p.Cell.Landblock != anchor.Landblock;
        return fault == Always2DIgnoredIndoors && indoor ? p with { Always2D = false }
            : fault == OwnCellFrame && indoor ? p with { Cell = anchor }
            : fault == EnvBlockOffsetDropped && p.Cell.IsEnv && otherBlock ? p with { Cell = anchor.WithLow(p.Cell.Low) }
            : p;
    }
}
