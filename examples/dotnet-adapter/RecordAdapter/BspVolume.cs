using System.Numerics;
using AcPhys.Core;

namespace RecordAdapter;

/// <summary>One node of a cell BSP as read from a record: its splitting plane and children (−1 none), or a leaf.</summary>
/// <param name="Plane">The splitting plane (all zero for a leaf).</param>
/// <param name="Positive">Index of the positive child, or −1.</param>
/// <param name="Negative">Index of the negative child, or −1 (kept, never followed).</param>
/// <param name="IsLeaf">True for a LEAF.</param>
internal readonly record struct BspNode(CellPlane Plane, int Positive, int Negative, bool IsLeaf);

/// <summary>
/// A cell's volume answered straight from its CellStruct's cell BSP with retail's semantics (facts §5.7): all three
/// queries walk the positive-child chain from the root and ignore negative children, so a cell made of several convex
/// pieces answers for the piece on the root's chain. The bounds are those of the CellStruct's face vertices.
/// </summary>
/// <param name="nodes">The nodes, root first.</param>
/// <param name="bounds">The cell-local bounds.</param>
internal sealed class BspVolume(BspNode[] nodes, Box bounds) : ICellVolume
{
    private const float SpherePadding = 0.01f; // BN:222 pads the radius by 0.01, not by EPS

    /// <inheritdoc/>
    public Box Bounds { get; } = bounds;

    /// <inheritdoc/>
    public bool PointInside(Vector3 p)
    {
        // Behind any plane of the chain (d < −EPS) is outside; a leaf or a node without a positive child ends it inside.
        for (int i = 0; i >= 0 && !nodes[i].IsLeaf; i = nodes[i].Positive)
        {
            if (nodes[i].Plane.Classify(p) == Side.Behind)
            {
                return false;
            }
        }

        return true;
    }

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere)
    {
        // d ≤ −R anywhere on the chain: outside. A chain ending in a leaf (whose zero plane always straddles) answers
        // partially inside; one ending in a node without a positive child answers entirely inside only if no plane
        // of the chain was straddled.
        float r = sphere.Radius + SpherePadding;
        bool straddled = false;
        for (int i = 0; ; i = nodes[i].Positive)
        {
            if (nodes[i].IsLeaf)
            {
                return BoundingType.PartiallyInside;
            }

            float d = nodes[i].Plane.Distance(sphere.Center);
            if (d <= -r)
            {
                return BoundingType.Outside;
            }

            straddled |= !(d >= r);
            if (nodes[i].Positive < 0)
            {
                return straddled ? BoundingType.PartiallyInside : BoundingType.EntirelyInside;
            }
        }
    }

    /// <inheritdoc/>
    public bool BoxIntersects(Box box)
    {
        // Continue where N·Min + D ≥ −EPS; elsewhere the box is outside when all eight corners are behind the plane.
        for (int i = 0; i >= 0 && !nodes[i].IsLeaf; i = nodes[i].Positive)
        {
            var plane = nodes[i].Plane;
            if (plane.Distance(box.Min) >= -LandDefs.Epsilon)
            {
                continue;
            }

            bool allBehind = true;
            for (int c = 0; c < 8 && allBehind; c++)
            {
                allBehind = plane.Classify(box.Corner(c)) == Side.Behind;
            }

            if (allBehind)
            {
                return false;
            }
        }

        return true;
    }
}
