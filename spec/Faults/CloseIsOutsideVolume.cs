using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A cell volume whose point test treats "Close" (|d| ≤ EPS) as outside: inside only when every plane of the positive
/// chain (piece 0) has d &gt; EPS. Retail's point_inside_cell_bsp moves on for Front and Close (facts §5.7: inside ⇔ d ≥ −EPS).
/// </summary>
/// <param name="inner">The retail volume (sphere and box tests).</param>
/// <param name="chain">Piece 0, whose planes form the positive chain.</param>
internal sealed class CloseIsOutsideVolume(ICellVolume inner, ConvexPiece chain) : ICellVolume
{
    /// <inheritdoc/>
    public Box Bounds => inner.Bounds;

    /// <inheritdoc/>
    public bool PointInside(Vector3 p)
    {
        foreach (var plane in chain.Planes)
        {
            if (plane.Classify(p) != Side.Front)
            {
                return false;
            }
        }

        return true;
    }

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere) => inner.SphereIntersects(sphere);

    /// <inheritdoc/>
    public bool BoxIntersects(Box box) => inner.BoxIntersects(box);
}
