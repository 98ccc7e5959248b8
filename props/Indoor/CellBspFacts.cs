using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Props.Indoor;

/// <summary>The cell BSP queries of facts §5.7 on a 1 m cube and an L-shaped union; the AABB mode beside them.</summary>
public sealed class CellBspFacts
{
    private static readonly CellBsp Cube = new([ConvexPiece.FromBox(Vector3.Zero, Vector3.One)]);

    private static readonly ConvexPiece[] LShape =
    [
        ConvexPiece.FromBox(Vector3.Zero, new Vector3(4, 2, 3)),
        ConvexPiece.FromBox(Vector3.Zero, new Vector3(2, 4, 3)),
    ];

    [Theory(DisplayName = "facts §5.7: point_inside is d ≥ −EPS on every plane of the positive chain")]
    [InlineData(-0.0001f, true)]
    [InlineData(-0.0003f, false)]
    [InlineData(1.0001f, true)]
    [InlineData(0.5f, true)]
    public void PointInsideEps(float x, bool inside) => Assert.Equal(inside, Cube.PointInside(new Vector3(x, 0.5f, 0.5f)));

    [Theory(DisplayName = "facts §5.7: sphere_intersects pads the radius by 0.01; a chain ending in a leaf never answers EntirelyInside")]
    [InlineData(-0.505f, BoundingType.PartiallyInside)]
    [InlineData(-0.515f, BoundingType.Outside)]
    [InlineData(0.5f, BoundingType.PartiallyInside)]
    public void SphereIntersectsPadding(float x, BoundingType expected) =>
        Assert.Equal(expected, Cube.SphereIntersects(new Sphere(new Vector3(x, 0.5f, 0.5f), x == 0.5f ? 0.1f : 0.5f)));

    [Fact(DisplayName = "facts §5.7: box_intersects is false only when all 8 corners are behind one chain plane")]
    public void BoxIntersects()
    {
        Assert.False(Cube.BoxIntersects(new Box(new Vector3(-2, 0, 0), new Vector3(-1, 1, 1))));
        Assert.True(Cube.BoxIntersects(new Box(new Vector3(-2, 0, 0), new Vector3(0.1f, 1, 1))));
        Assert.True(Cube.BoxIntersects(new Box(new Vector3(-2, 0, 0), new Vector3(-0.0001f, 1, 1)))); // the far corners are Close
    }

    [Theory(DisplayName = "facts §5.7: a box wholly outside any one face of a cube does not intersect it; moved a tenth as far, it does")]
    [InlineData(-3f, 0f, 0f)]
    [InlineData(3f, 0f, 0f)]
    [InlineData(0f, -3f, 0f)]
    [InlineData(0f, 3f, 0f)]
    [InlineData(0f, 0f, -3f)]
    [InlineData(0f, 0f, 3f)]
    public void BoxOutsideEachFace(float dx, float dy, float dz)
    {
        // The unit box moved three widths along one axis: outside exactly one face, level with the cube on the others.
        var shift = new Vector3(dx, dy, dz);
        Assert.False(Cube.BoxIntersects(new Box(shift, Vector3.One + shift)));
        Assert.True(Cube.BoxIntersects(new Box(shift * 0.1f, Vector3.One + (shift * 0.1f))));
    }

    [Fact(DisplayName = "Unions: retail's positive chain answers for the first piece only; the AABB over-covers the union's box")]
    public void LShapeUnion()
    {
        var bsp = new CellBsp(LShape);
        var aabb = new CellAabb(LShape);
        var armA = new Vector3(3, 1, 1);
        var armB = new Vector3(1, 3, 1);
        var notch = new Vector3(3, 3, 1);
        Assert.True(bsp.PointInside(armA) && aabb.PointInside(armA));
        Assert.False(bsp.PointInside(armB)); // second piece: under a negative child, ignored by the query
        Assert.True(aabb.PointInside(armB));
        Assert.False(bsp.PointInside(notch));
        Assert.True(aabb.PointInside(notch)); // outside the union, inside its box
        Assert.Equal(new Box(Vector3.Zero, new Vector3(4, 4, 3)), bsp.Bounds);
        Assert.Equal(2 * 7, bsp.NodeCount); // 6 planes + 1 leaf per piece
    }

    [Fact(DisplayName = "A plane-defined piece with the planes of a box answers as the box")]
    public void PlanePieceMatchesBox()
    {
        var planes = ConvexPiece.FromBox(Vector3.Zero, Vector3.One).Planes;
        var piece = new ConvexPiece(planes);
        Assert.Equal(8, piece.Vertices.Count);
        Assert.Equal(new Box(Vector3.Zero, Vector3.One), piece.Bounds);
    }

    [Fact(DisplayName = "A piece whose planes bound no finite volume is refused")]
    public void UnboundedPieceRefused()
    {
        var planes = ConvexPiece.FromBox(Vector3.Zero, Vector3.One).Planes.Take(5).Append(new CellPlane(Vector3.UnitX, 5)).ToArray();
        Assert.Throws<ArgumentException>(() => new ConvexPiece(planes));
    }
}
