using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A cell volume whose sphere test is a port's variant of sphere_intersects_cell_bsp (facts §5.7, BN:219-240): along
/// the positive chain (piece 0) Outside iff some plane's distance d to the centre is outside by the variant's rule,
/// else PartiallyInside (the leaf straddles); point and box tests stay retail's. Retail's rule is d ≤ −(r + 0.01).
/// </summary>
/// <param name="inner">The retail volume (point and box tests).</param>
/// <param name="chain">Piece 0, whose planes form the positive chain.</param>
/// <param name="isOutside">The variant's rule: whether a plane at distance d puts a sphere of radius r outside.</param>
internal sealed class ChainSphereVolume(ICellVolume inner, ConvexPiece chain, Func<float, float, bool> isOutside) : ICellVolume
{
    /// <summary>The bound taken strictly: d &lt; −(r + 0.01), so a sphere exactly at the bound is inside.</summary>
    public static bool StrictBound(float d, float r) => d < -(r + 0.01f);

    /// <summary>The +0.01 padding forgotten (facts §6.10): d ≤ −r.</summary>
    public static bool Unpadded(float d, float r) => d <= -r;

    /// <inheritdoc/>
    public Box Bounds => inner.Bounds;

    /// <inheritdoc/>
    public bool PointInside(Vector3 p) => inner.PointInside(p);

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere)
    {
        foreach (var plane in chain.Planes)
        {
            if (isOutside(plane.Distance(sphere.Center), sphere.Radius))
            {
                return BoundingType.Outside;
            }
        }

        return BoundingType.PartiallyInside;
    }

    /// <inheritdoc/>
    public bool BoxIntersects(Box box) => inner.BoxIntersects(box);
}
