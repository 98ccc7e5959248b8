using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>Which of a CellStruct's trees a node belongs to: it decides the node's trailing fields (dat-records.md, BSP node).</summary>
public enum BspTreeType
{
    /// <summary>The cell BSP (membership queries).</summary>
    Cell,

    /// <summary>The physics BSP (spheres, leaf polygons).</summary>
    Physics,

    /// <summary>The drawing BSP (spheres, polygons, portal lists).</summary>
    Drawing,
}

/// <summary>
/// One BSP node as stored: tag, plane and children, plus the per-tree trailing fields. Leaves carry the all-zero
/// plane (facts §5.7).
/// </summary>
/// <param name="Tag">The tag as the u32 of its 4 ASCII letters read big-endian (stored reversed: <c>BPnn</c> is the bytes n n P B).</param>
/// <param name="Plane">The splitting plane (zero for a leaf).</param>
/// <param name="Positive">The positive child, or null.</param>
/// <param name="Negative">The negative child, or null.</param>
public sealed record BspNode(uint Tag, CellPlane Plane, BspNode? Positive, BspNode? Negative)
{
    /// <summary>Gets the byte offset the node was read from (0 for nodes built in memory).</summary>
    public int Offset { get; init; }

    /// <summary>Gets the leaf index (leaves only).</summary>
    public int LeafIndex { get; init; }

    /// <summary>Gets the physics leaf's solid flag.</summary>
    public int Solid { get; init; }

    /// <summary>Gets the bounding sphere (physics and drawing trees).</summary>
    public Sphere Sphere { get; init; }

    /// <summary>Gets the polygon ids (physics leaves, drawing nodes).</summary>
    public IReadOnlyList<ushort> Polygons { get; init; } = [];

    /// <summary>Gets a drawing PORT node's (portal index, polygon id) pairs.</summary>
    public IReadOnlyList<(short Portal, short Polygon)> Portals { get; init; } = [];

    /// <summary>Gets a value indicating whether this is a leaf.</summary>
    public bool IsLeaf => Tag == BspTags.Leaf;

    /// <summary>Returns a leaf.</summary>
    /// <param name="index">The leaf index.</param>
    /// <returns>The leaf.</returns>
    public static BspNode NewLeaf(int index) => new(BspTags.Leaf, default, null, null) { LeafIndex = index };

    /// <summary>Returns an internal node with the tag its children call for (BPnn, BpnN or BPnN).</summary>
    /// <param name="plane">The splitting plane.</param>
    /// <param name="positive">Positive child.</param>
    /// <param name="negative">Negative child.</param>
    /// <returns>The node.</returns>
    public static BspNode Internal(CellPlane plane, BspNode? positive, BspNode? negative) =>
        new(BspTags.For(positive is not null, negative is not null), plane, positive, negative);
}
