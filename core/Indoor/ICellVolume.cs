namespace AcPhys.Core;

/// <summary>The three geometric questions membership asks of an env cell's structure, in the cell's local frame (facts §5.5, §5.7).</summary>
public interface ICellVolume
{
    /// <summary><c>point_inside_cell_bsp</c>: whether a local point is in the cell.</summary>
    /// <param name="p">A cell-local point.</param>
    /// <returns>True when inside.</returns>
    bool PointInside(System.Numerics.Vector3 p);

    /// <summary><c>sphere_intersects_cell</c> (the +0.01 padding is applied inside).</summary>
    /// <param name="sphere">A cell-local sphere, radius unpadded.</param>
    /// <returns>Outside, partially or entirely inside.</returns>
    BoundingType SphereIntersects(Sphere sphere);

    /// <summary><c>box_intersects_cell</c>.</summary>
    /// <param name="box">A cell-local box.</param>
    /// <returns>True unless the box is certainly outside.</returns>
    bool BoxIntersects(Box box);

    /// <summary>Gets the cell-local axis-aligned bounds of the cell's pieces.</summary>
    Box Bounds { get; }
}

/// <summary>How a cell's pieces are turned into a volume.</summary>
public enum VolumeMode
{
    /// <summary>A cell BSP with retail's positive-chain query semantics (facts §5.7).</summary>
    Bsp,

    /// <summary>The ACME editor's cell-local AABB with a 0.01 tolerance: faster, less exact (seed, "point_in_cell — two implementations").</summary>
    Aabb,
}
