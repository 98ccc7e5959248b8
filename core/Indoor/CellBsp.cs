using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// A cell BSP with retail's query semantics (facts §5.7): nodes carry a splitting plane and children, leaves carry
/// the all-zero plane, and all three queries follow the positive-child chain only (negative children are ignored).
/// </summary>
/// <remarks>
/// <para>Built from a union of convex pieces: piece 0's planes form the positive chain (ending in a leaf), and every
/// further piece hangs as a subtree under the negative child of the root — where a full BSP traversal would find it
/// and retail's queries never look. So under retail semantics a cell answers for its first piece only; an L-shaped
/// room's second arm or a staircase's upper steps are not in the cell (docs/indoor.md, "Unions and the positive
/// chain"). The AABB mode covers the union's bounding box instead; the differential property measures the gap.</para>
/// <para>Queries do not allocate.</para>
/// </remarks>
public sealed class CellBsp : ICellVolume
{
    private const float SpherePadding = 0.01f; // BN:222, not EPS (facts §1.5)
    private readonly Node[] nodes;

    /// <summary>Initializes a new instance from pieces.</summary>
    /// <param name="pieces">At least one convex piece.</param>
    public CellBsp(IReadOnlyList<ConvexPiece> pieces)
    {
        Bounds = ConvexPiece.BoundsOf(pieces); // first: it refuses an empty list

        var list = new List<Node>();
        int root = Chain(list, pieces[0]);
        int negative = -1;
        for (int i = pieces.Count - 1; i >= 1; i--)
        {
            // Each further piece: its own chain, reached only through negative children (ignored by the queries).
            int sub = Chain(list, pieces[i]);
            list[sub] = list[sub] with { Negative = negative };
            negative = sub;
        }

        list[root] = list[root] with { Negative = negative };
        nodes = [.. list];
        Root = root;
    }

    /// <inheritdoc/>
    public Box Bounds { get; }

    /// <summary>Gets the number of nodes including leaves (the whole tree, negative subtrees included).</summary>
    public int NodeCount => nodes.Length;

    private int Root { get; }

    /// <inheritdoc/>
    public bool PointInside(Vector3 p)
    {
        // BN:191-209: Behind → false; Front/Close → positive child; none → true. A leaf's zero plane is Close.
        for (int i = Root; i >= 0; i = nodes[i].Positive)
        {
            if (nodes[i].Plane.Classify(p) == Side.Behind)
            {
                return false;
            }
        }

        return true;
    }

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere) => SphereAt(Root, sphere.Center, sphere.Radius + SpherePadding);

    /// <inheritdoc/>
    public bool BoxIntersects(Box box)
    {
        // BN:118-139: continue where N·Min + D ≥ −EPS; otherwise outside iff all 8 corners are Behind.
        for (int i = Root; i >= 0; i = nodes[i].Positive)
        {
            var plane = nodes[i].Plane;
            if (plane.Distance(box.Min) >= -LandDefs.Epsilon)
            {
                continue;
            }

            if (AllBehind(plane, box))
            {
                return false;
            }
        }

        return true;
    }

    private static bool AllBehind(CellPlane plane, Box b)
    {
        for (int c = 0; c < 8; c++)
        {
            var corner = b.Corner(c);
            if (plane.Classify(corner) != Side.Behind)
            {
                return false;
            }
        }

        return true;
    }

    private static int Chain(List<Node> list, ConvexPiece piece)
    {
        int leaf = list.Count;
        list.Add(new Node(default, -1, -1, true));
        int next = leaf;
        for (int i = piece.Planes.Count - 1; i >= 0; i--)
        {
            list.Add(new Node(piece.Planes[i], next, -1, false));
            next = list.Count - 1;
        }

        return next;
    }

    private BoundingType SphereAt(int i, Vector3 c, float r)
    {
        // BN:219-240, R = r + 0.01. A leaf's zero plane always straddles: PartiallyInside.
        var node = nodes[i];
        if (node.IsLeaf)
        {
            return BoundingType.PartiallyInside;
        }

        float d = node.Plane.Distance(c);
        if (d <= -r)
        {
            return BoundingType.Outside;
        }

        // Retail also handles a plane node without a positive child; every chain built here ends in a leaf, so a
        // plane node always has one.
        if (d >= r)
        {
            return SphereAt(node.Positive, c, r);
        }

        return SphereAt(node.Positive, c, r) != BoundingType.Outside ? BoundingType.PartiallyInside : BoundingType.Outside;
    }

    private readonly record struct Node(CellPlane Plane, int Positive, int Negative, bool IsLeaf);
}
