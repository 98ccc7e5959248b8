using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Dat;

namespace AcPhys.Props.Dat;

/// <summary>
/// An independent evaluator of a parsed cell BSP with retail's semantics (facts §5.7): only the positive chain is
/// followed; point_inside ⇔ d ≥ −EPS on every plane of the chain; sphere_intersects with R = r + 0.01.
/// </summary>
internal static class RecordBspEvaluator
{
    /// <summary>point_inside_cell_bsp.</summary>
    /// <param name="root">The parsed root.</param>
    /// <param name="p">A cell-local point.</param>
    /// <returns>True when inside.</returns>
    public static bool PointInside(BspNode root, Vector3 p)
    {
        for (var n = root; n is { IsLeaf: false }; n = n.Positive)
        {
            if (Vector3.Dot(n.Plane.Normal, p) + n.Plane.D < -LandDefs.Epsilon)
            {
                return false;
            }
        }

        return true;
    }

    /// <summary>sphere_intersects_cell_bsp.</summary>
    /// <param name="root">The parsed root.</param>
    /// <param name="c">Cell-local centre.</param>
    /// <param name="r">Radius.</param>
    /// <returns>The answer.</returns>
    public static BoundingType Sphere(BspNode root, Vector3 c, float r) => At(root, c, r + 0.01f);

    private static BoundingType At(BspNode n, Vector3 c, float r)
    {
        if (n.IsLeaf)
        {
            return BoundingType.PartiallyInside; // the zero plane straddles
        }

        float d = Vector3.Dot(n.Plane.Normal, c) + n.Plane.D;
        if (d <= -r)
        {
            return BoundingType.Outside;
        }

        if (d >= r)
        {
            return n.Positive is { } p ? At(p, c, r) : BoundingType.EntirelyInside;
        }

        return n.Positive is { } q ? (At(q, c, r) != BoundingType.Outside ? BoundingType.PartiallyInside : BoundingType.Outside) : BoundingType.PartiallyInside;
    }
}
