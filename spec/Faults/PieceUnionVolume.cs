using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A cell volume that walks the negative children too: the point and sphere tests answer for the union of all pieces.
/// Retail's cell queries follow the positive chain only (facts §5.7, §6.16), so a cell answers for piece 0 alone.
/// </summary>
/// <param name="inner">The retail volume (box test).</param>
/// <param name="pieces">Every piece of the cell.</param>
internal sealed class PieceUnionVolume(ICellVolume inner, IReadOnlyList<ConvexPiece> pieces) : ICellVolume
{
    private const float SpherePadding = 0.01f;

    /// <inheritdoc/>
    public Box Bounds => inner.Bounds;

    /// <inheritdoc/>
    public bool PointInside(Vector3 p) => pieces.Any(piece => piece.Planes.All(plane => plane.Classify(p) != Side.Behind));

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere) =>
        pieces.Any(piece => piece.Planes.All(plane => plane.Distance(sphere.Center) > -(sphere.Radius + SpherePadding)))
            ? BoundingType.PartiallyInside
            : BoundingType.Outside;

    /// <inheritdoc/>
    public bool BoxIntersects(Box box) => inner.BoxIntersects(box);
}
