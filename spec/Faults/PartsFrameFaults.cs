using AcPhys.Contract;

namespace AcPhys.Spec.Faults;

/// <summary>
/// Planted faults of how a port reads a part's frame and box in the parts variant indoors (issue 41, "frames"): each
/// misreads every part the same way (<see cref="PartsMisread"/>) and then answers as the reference, so the defect is
/// the reading alone. The parts a scene walk stands for (spec/Cases/PartShapes, PartFrames) are shaped so each reading
/// changes some box: off-centre boxes of unequal sides, pitched and rolled parts, parts framed in another block.
/// </summary>
internal static class PartsFrameFaults
{
    /// <summary>The inverse rotation.</summary>
    public static readonly PlantedFault RotationInverted = new(
        "parts-rotation-inverted",
        "a part's box is rotated by the conjugate of its frame's rotation (GlobalToLocal where LocalToGlobal belongs)",
        "facts §5.8: the box's corners go local → global by the part's frame, R·p; a port that applies Rᵀ (the cell-frame direction) gets the mirror-turned box, which is the same hull only for a cube centred on the origin.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Only the heading of the rotation.</summary>
    public static readonly PlantedFault YawOnly = new(
        "parts-yaw-only",
        "a part's rotation is reduced to its heading (the yaw about z): pitch and roll are dropped",
        "facts §5.8: the frame's rotation is a full quaternion; a port that keeps objects upright (a heading, as its outdoor code needs for the 2D cell range) turns a tilted part's box wrongly.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>The box taken as centred on the part's origin.</summary>
    public static readonly PlantedFault BoxCentred = new(
        "parts-box-centred",
        "a part's box is taken centred on the part's origin (its size kept, its offset dropped: min = −max)",
        "facts §3.4, §5.8: a part's bounding box is a min and a max corner in the part's frame, not half extents; a port storing half extents centres every box on the origin.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Every part framed in the anchor's cell.</summary>
    public static readonly PlantedFault AnchorFrame = new(
        "parts-anchor-frame",
        "every part's origin is taken in the anchor's (first part's) cell and block frame, not its own cell's",
        "facts §3.4, §5.2: each part carries its own cell, and GetBlockOffset(cell, part's cell) re-frames it; a port that frames the object once by its anchor puts a part held in the neighbouring block 192 m away.",
        ["PARTS-INDOOR-SOUNDNESS", "PARTS-INDOOR-COVERAGE", "PARTS-BUILDING-ENTRY", "PARTS-INDOOR-CONFORMANCE"]);

    /// <summary>Gets every frame fault of the parts variant indoors.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [RotationInverted, YawOnly, BoxCentred, AnchorFrame];

    /// <summary>Returns an adapter carrying a frame fault of the parts variant indoors, or null for another fault.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The adapter, or null.</returns>
    public static ICellPhysics? Create(PlantedFault fault) => All.Contains(fault) ? new PartsMisreadPhysics(fault) : null;
}
