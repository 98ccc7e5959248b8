using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A cell volume whose sphere test forgets the +0.01 padding of sphere_intersects_cell_bsp (facts §5.7, §6.10):
/// along the positive chain (piece 0) Outside iff some plane has d ≤ −r, else PartiallyInside (the leaf straddles).
/// </summary>
/// <param name="inner">The retail volume (point and box tests).</param>
/// <param name="chain">Piece 0, whose planes form the positive chain.</param>
internal sealed class UnpaddedSphereVolume(ICellVolume inner, ConvexPiece chain) : ICellVolume
{
    /// <inheritdoc/>
    public Box Bounds => inner.Bounds;

    /// <inheritdoc/>
    public bool PointInside(Vector3 p) => inner.PointInside(p);

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere)
    {
        foreach (var plane in chain.Planes)
        {
            if (plane.Distance(sphere.Center) <= -sphere.Radius)
            {
                return BoundingType.Outside;
            }
        }

        return BoundingType.PartiallyInside;
    }

    /// <inheritdoc/>
    public bool BoxIntersects(Box box) => inner.BoxIntersects(box);
}
