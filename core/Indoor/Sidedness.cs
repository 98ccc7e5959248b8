using System.Numerics;

namespace AcPhys.Core;

/// <summary>Which side of a plane a box lies on (EN/Sidedness.cs; the values coincide with the side classes).</summary>
public enum Sidedness
{
    /// <summary>Every corner in front.</summary>
    Positive = 0,

    /// <summary>Every corner behind.</summary>
    Negative = 1,

    /// <summary>In the plane.</summary>
    InPlane = 2,

    /// <summary>Corners on different sides.</summary>
    Crossing = 3,
}

/// <summary><c>Plane.intersect_box</c> (facts §5.7, PE:49-72).</summary>
public static class BoxSide
{
    /// <summary>
    /// Classifies a box: d(Min) within ±EPS → Crossing; else provisionally Positive or Negative by d(Min); each corner is
    /// classified with bias +EPS (Front → Positive, Behind → Negative, Close → InPlane); any corner that differs → Crossing.
    /// </summary>
    /// <param name="plane">The plane.</param>
    /// <param name="box">The box, in the plane's frame.</param>
    /// <returns>The sidedness.</returns>
    public static Sidedness Of(CellPlane plane, Box box)
    {
        float d = plane.Distance(box.Min);
        if (d >= -LandDefs.Epsilon && d <= LandDefs.Epsilon)
        {
            return Sidedness.Crossing;
        }

        var provisional = d > LandDefs.Epsilon ? Sidedness.Positive : Sidedness.Negative;
        for (int c = 0; c < 8; c++)
        {
            var corner = box.Corner(c);
            var side = plane.Classify(corner, LandDefs.Epsilon) switch
            {
                Side.Front => Sidedness.Positive,
                Side.Behind => Sidedness.Negative,
                _ => Sidedness.InPlane,
            };
            if (side != provisional)
            {
                return Sidedness.Crossing;
            }
        }

        return provisional;
    }

    /// <summary>Returns the axis-aligned box, in a target frame, around a part's local box (all 8 corners folded; ACE's BBox folds 6, facts §5.8).</summary>
    /// <param name="part">The part.</param>
    /// <param name="target">The target cell (its id gives the block, its frame the rotation).</param>
    /// <param name="targetFrame">The target cell's frame.</param>
    /// <returns>The box.</returns>
    public static Box InFrame(Part part, CellId target, Frame targetFrame)
    {
        var offset = LandDefs.GetBlockOffset(target, part.Cell);
        var min = new Vector3(float.MaxValue);
        var max = new Vector3(float.MinValue);
        var b = part.Bounds;
        for (int c = 0; c < 8; c++)
        {
            var corner = b.Corner(c);
            var p = targetFrame.GlobalToLocal(part.Frame.LocalToGlobal(corner) + offset);
            min = Vector3.Min(min, p);
            max = Vector3.Max(max, p);
        }

        return new Box(min, max);
    }
}
