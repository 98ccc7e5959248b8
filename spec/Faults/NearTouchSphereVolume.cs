using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A cell volume whose sphere test pads the radius by another value than sphere_intersects_cell_bsp's 0.01 (facts §5.7:
/// R = r + 0.01, Outside iff some plane on the positive chain has d ≤ −R).
/// </summary>
/// <param name="inner">The retail volume (point and box tests).</param>
/// <param name="chain">Piece 0, whose planes form the positive chain.</param>
/// <param name="pad">The padding added to the radius.</param>
internal sealed class NearTouchSphereVolume(ICellVolume inner, ConvexPiece chain, float pad) : ICellVolume
{
    /// <inheritdoc/>
    public Box Bounds => inner.Bounds;

    /// <inheritdoc/>
    public bool PointInside(Vector3 p) => inner.PointInside(p);

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere)
    {
        float r = sphere.Radius + pad;
        foreach (var plane in chain.Planes)
        {
            if (plane.Distance(sphere.Center) <= -r)
            {
                return BoundingType.Outside;
            }
        }

        return BoundingType.PartiallyInside;
    }

    /// <inheritdoc/>
    public bool BoxIntersects(Box box) => inner.BoxIntersects(box);
}
