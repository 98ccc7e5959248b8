using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Studies.Numerics;

/// <summary>
/// The boundary class of an indoor query for the AABB-vs-BSP table: where the body is relative to the scene's cells,
/// judged per sphere in each nearby cell's local frame, most specific first. <see cref="Band"/> covers both modes'
/// tolerances (EPS 0.0002, the BSP's 0.01 sphere padding, the AABB's 0.01). Classes: <c>portal-straddle</c>, a
/// sphere crosses (within radius + band) the plane of one of a nearby cell's portals; <c>wall</c>, else one of a
/// piece's face planes; <c>union-arm</c>, else a centre inside a cell's bounding box but outside its first piece (the
/// only piece retail's BSP queries see: a union's further pieces, or the gap an L leaves); <c>interior</c>, else inside
/// a first piece; <c>outdoor-near</c>, within 2 m of a cell's box; <c>outdoor</c>, farther.
/// </summary>
public static class IndoorAccuracyClass
{
    /// <summary>Distance added to a radius within which a sphere counts as touching a plane or a cell's box, metres.</summary>
    public const float Band = 0.02f;

    /// <summary>How far outside every cell's box a body still counts as next to the building, metres.</summary>
    public const float Near = 2f;

    /// <summary>Gets the classes, most specific first.</summary>
    public static IReadOnlyList<string> All { get; } = ["portal-straddle", "wall", "union-arm", "interior", "outdoor-near", "outdoor"];

    /// <summary>Returns the class of a query.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The position's cell (the spheres' block frame).</param>
    /// <param name="spheres">Sphere centres in that frame.</param>
    /// <returns>One of <see cref="All"/>.</returns>
    public static string Of(Scene scene, CellId position, IReadOnlyList<Sphere> spheres)
    {
        int best = All.Count - 1;
        foreach (var cell in scene.Cells)
        {
            var frame = new Frame(cell.Origin, cell.Rotation);
            var offset = LandDefs.GetBlockOffset(position, cell.Id);
            var pieces = cell.Pieces.Select(p => p.ToConvex()).ToArray();
            var bounds = ConvexPiece.BoundsOf(pieces);
            foreach (var s in spheres)
            {
                var local = frame.GlobalToLocal(s.Center - offset);
                best = Math.Min(best, Classify(cell, pieces, bounds, local, s.Radius));
            }
        }

        return All[best];
    }

    /// <summary>Returns sphere 0's centre in the local frame of the cell nearest to it, as "cell (x, y, z)", for examples.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="position">The position's cell.</param>
    /// <param name="center">Sphere 0's centre in its block frame.</param>
    /// <returns>The text, or empty without cells.</returns>
    public static string Where(Scene scene, CellId position, Vector3 center)
    {
        string text = string.Empty;
        float nearest = float.MaxValue;
        foreach (var cell in scene.Cells)
        {
            var local = new Frame(cell.Origin, cell.Rotation).GlobalToLocal(center - LandDefs.GetBlockOffset(position, cell.Id));
            var bounds = ConvexPiece.BoundsOf([.. cell.Pieces.Select(p => p.ToConvex())]);
            float d = Vector3.Distance(Vector3.Clamp(local, bounds.Min, bounds.Max), local);
            if (d < nearest)
            {
                nearest = d;
                text = FormattableString.Invariant($"{cell.Id} local ({local.X:0.###}, {local.Y:0.###}, {local.Z:0.###}) in box ({bounds.Min.X:0.##}, {bounds.Min.Y:0.##}, {bounds.Min.Z:0.##})–({bounds.Max.X:0.##}, {bounds.Max.Y:0.##}, {bounds.Max.Z:0.##})");
            }
        }

        return text;
    }

    private static int Classify(SceneCell cell, ConvexPiece[] pieces, Box bounds, Vector3 c, float r)
    {
        // Per axis (not Euclidean): the BSP tests a sphere plane by plane, so near an edge or a corner of the box it
        // counts as touching where the true distance is already beyond the radius; that is a wall case, not an outdoor one.
        float reach = r + Band;
        var gap = Vector3.Abs(Vector3.Clamp(c, bounds.Min, bounds.Max) - c);
        float outside = MathF.Max(gap.X, MathF.Max(gap.Y, gap.Z));
        if (outside > reach)
        {
            return outside <= r + Near ? 4 : 5;
        }

        foreach (var portal in cell.Portals)
        {
            var n = portal.Plane.Normal;
            if (MathF.Abs((Vector3.Dot(n, c) + portal.Plane.D) / n.Length()) < reach)
            {
                return 0;
            }
        }

        foreach (var piece in pieces)
        {
            var grown = new Vector3(reach);
            bool nearPiece = Vector3.Clamp(c, piece.Bounds.Min - grown, piece.Bounds.Max + grown) == c;
            if (nearPiece && piece.Planes.Any(p => MathF.Abs(p.Distance(c)) < reach))
            {
                return 1;
            }
        }

        return pieces[0].Contains(c) ? 3 : 2;
    }
}
