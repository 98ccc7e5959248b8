using System.Numerics;

namespace AcPhys.Core;

/// <summary>
/// The ACME editor's approximation of a cell: the cell-local axis-aligned box of all its pieces' vertices, with a
/// 0.01 tolerance (seed, "point_in_cell — two implementations"). Exact for box rooms, over-covers any other shape.
/// </summary>
/// <param name="bounds">The cell-local bounds.</param>
public sealed class CellAabb(Box bounds) : ICellVolume
{
    private const float Tolerance = 0.01f;

    /// <summary>Initializes a new instance from pieces.</summary>
    /// <param name="pieces">At least one piece.</param>
    public CellAabb(IReadOnlyList<ConvexPiece> pieces)
        : this(ConvexPiece.BoundsOf(pieces))
    {
    }

    /// <inheritdoc/>
    public Box Bounds { get; } = bounds;

    /// <inheritdoc/>
    public bool PointInside(Vector3 p) =>
        p.X >= Bounds.Min.X - Tolerance && p.X <= Bounds.Max.X + Tolerance
        && p.Y >= Bounds.Min.Y - Tolerance && p.Y <= Bounds.Max.Y + Tolerance
        && p.Z >= Bounds.Min.Z - Tolerance && p.Z <= Bounds.Max.Z + Tolerance;

    /// <inheritdoc/>
    public BoundingType SphereIntersects(Sphere sphere)
    {
        float r = sphere.Radius + Tolerance;
        var c = sphere.Center;
        var nearest = Vector3.Clamp(c, Bounds.Min, Bounds.Max);
        if (Vector3.DistanceSquared(nearest, c) > r * r)
        {
            return BoundingType.Outside;
        }

        bool inside = c.X - r >= Bounds.Min.X && c.X + r <= Bounds.Max.X && c.Y - r >= Bounds.Min.Y && c.Y + r <= Bounds.Max.Y
            && c.Z - r >= Bounds.Min.Z && c.Z + r <= Bounds.Max.Z;
        return inside ? BoundingType.EntirelyInside : BoundingType.PartiallyInside;
    }

    /// <inheritdoc/>
    public bool BoxIntersects(Box box) =>
        box.Min.X <= Bounds.Max.X + Tolerance && box.Max.X >= Bounds.Min.X - Tolerance
        && box.Min.Y <= Bounds.Max.Y + Tolerance && box.Max.Y >= Bounds.Min.Y - Tolerance
        && box.Min.Z <= Bounds.Max.Z + Tolerance && box.Max.Z >= Bounds.Min.Z - Tolerance;
}
