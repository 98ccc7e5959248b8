using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A cell volume whose sphere test takes its bound strictly: Outside iff some plane on the positive chain has
/// d &lt; −(r + 0.01), where retail says d ≤ −R (facts §5.7, BN:219-240), so a sphere exactly at the bound is inside.
/// </summary>
/// <param name="inner">The retail volume (point and box tests).</param>
/// <param name="chain">Piece 0, whose planes form the positive chain.</param>
internal sealed class StrictBoundSphereVolume(ICellVolume inner, ConvexPiece chain) : ICellVolume
{
    /// <inheritdoc/>
    public Box Bounds => inner.Bounds;

    /// <inheritdoc/>
    public bool PointInside(Vector3 p) => inner.PointInside(p);

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere)
    {
        float r = sphere.Radius + 0.01f;
        foreach (var plane in chain.Planes)
        {
            if (plane.Distance(sphere.Center) < -r)
            {
                return BoundingType.Outside;
            }
        }

        return BoundingType.PartiallyInside;
    }

    /// <inheritdoc/>
    public bool BoxIntersects(Box box) => inner.BoxIntersects(box);
}
