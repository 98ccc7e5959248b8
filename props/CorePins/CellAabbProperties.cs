using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The ACME editor's AABB cell volume (seed, "point_in_cell — two implementations") read as interval statements: the
/// point and sphere tests at the 0.01 tolerance, inclusive at exactly the tolerance, and the bounds of several pieces.
/// Faces sit exactly at ± the tolerated distance, so a strict/inclusive or sign slip changes an answer.
/// </summary>
public sealed class CellAabbProperties
{
    private const float Tol = 0.01f;

    [FixedSeedProperty(0x1D00_0010, DisplayName = "seed point_in_cell (ACME): a point is inside the AABB volume iff each coordinate lies in [min − 0.01, max + 0.01], ends included")]
    public Property PointInside_IsTheToleratedBox() =>
        Prop.ForAll(PointCases.ToArbitrary(), t =>
        {
            var (bounds, p) = t;
            static bool In(float v, float lo, float hi) => v >= lo - Tol && v <= hi + Tol;
            bool expected = In(p.X, bounds.Min.X, bounds.Max.X) && In(p.Y, bounds.Min.Y, bounds.Max.Y) && In(p.Z, bounds.Min.Z, bounds.Max.Z);
            bool onEdge = new[] { (p.X, bounds.Min.X, bounds.Max.X), (p.Y, bounds.Min.Y, bounds.Max.Y), (p.Z, bounds.Min.Z, bounds.Max.Z) }
                .Any(a => a.Item1 == a.Item2 - Tol || a.Item1 == a.Item3 + Tol);
            return (new CellAabb(bounds).PointInside(p) == expected)
                .Classify(expected, "inside").Classify(!expected, "outside").Classify(onEdge, "a coordinate exactly at the tolerance");
        });

    [FixedSeedProperty(0x1D00_0011, DisplayName = "seed point_in_cell (ACME): with R = r + 0.01, a sphere is Outside iff the box is farther than R from its centre, EntirelyInside iff the R-ball fits in the box on every axis (ends included), else PartiallyInside")]
    public Property SphereIntersects_IsTheToleratedBall() =>
        Prop.ForAll(SphereCases.ToArbitrary(), t =>
        {
            var (bounds, sphere) = t;
            float r = sphere.Radius + Tol;
            var c = sphere.Center;
            float Gap(float v, float lo, float hi) => v < lo ? lo - v : v > hi ? v - hi : 0f;
            float gx = Gap(c.X, bounds.Min.X, bounds.Max.X), gy = Gap(c.Y, bounds.Min.Y, bounds.Max.Y), gz = Gap(c.Z, bounds.Min.Z, bounds.Max.Z);
            bool Fits(float v, float lo, float hi) => v - r >= lo && v + r <= hi;

            // Exact where it matters: the generated cases that touch R have only one non-zero gap.
            var expected = (gx * gx) + (gy * gy) + (gz * gz) > r * r ? BoundingType.Outside
                : Fits(c.X, bounds.Min.X, bounds.Max.X) && Fits(c.Y, bounds.Min.Y, bounds.Max.Y) && Fits(c.Z, bounds.Min.Z, bounds.Max.Z) ? BoundingType.EntirelyInside
                : BoundingType.PartiallyInside;
            bool touching = MathF.Max(gx, MathF.Max(gy, gz)) == r || new[] { c.X - r == bounds.Min.X, c.X + r == bounds.Max.X, c.Y - r == bounds.Min.Y, c.Z + r == bounds.Max.Z }.Any(b => b);
            return (new CellAabb(bounds).SphereIntersects(sphere) == expected).Collect(expected).Classify(touching, "touching at exactly R");
        });

    [FixedSeedProperty(0x1D00_0012, DisplayName = "facts §5.7, seed point_in_cell (ACME): the bounds of a cell volume (AABB or BSP) of several pieces are the per-axis min and max over every piece's bounds, whichever piece holds them")]
    public Property Bounds_AreTheUnionOfThePieces() =>
        Prop.ForAll(PieceBoxes.ToArbitrary(), boxes =>
        {
            var pieces = boxes.Select(b => ConvexPiece.FromBox(b.Min, b.Max)).ToArray();
            var min = pieces.Select(p => p.Bounds.Min).Aggregate(Vector3.Min);
            var max = pieces.Select(p => p.Bounds.Max).Aggregate(Vector3.Max);
            var aabb = new CellAabb(pieces).Bounds;
            var bsp = new CellBsp(pieces).Bounds;
            bool firstHoldsAll = pieces[0].Bounds.Min == min && pieces[0].Bounds.Max == max;
            return (aabb.Min == min && aabb.Max == max && bsp.Min == min && bsp.Max == max).Collect($"{pieces.Length} pieces").Classify(!firstHoldsAll, "an extreme outside piece 0");
        });

    // Boxes on a half-metre grid, flat ones included where no piece is built from them.
    private static Gen<Box> GridBoxes { get; } = Boxes(0);

    // Bounds on a half-metre grid; each coordinate of the point is an exact tolerated face, one ULP either side of it,
    // a face itself, inside, or far away.
    private static Gen<(Box Bounds, Vector3 Point)> PointCases { get; } =
        from bounds in GridBoxes
        from x in Coordinate(bounds.Min.X, bounds.Max.X)
        from y in Coordinate(bounds.Min.Y, bounds.Max.Y)
        from z in Coordinate(bounds.Min.Z, bounds.Max.Z)
        select (bounds, new Vector3(x, y, z));

    // The centre at the origin with faces at exactly ±R, one ULP beyond, half R or R + 1 (so DistanceSquared is exact
    // on the one axis that misses), or an arbitrary centre and grid box.
    private static Gen<(Box Bounds, Sphere Sphere)> SphereCases { get; } = Gen.Frequency(
        (3, from radius in Gen.Elements(0f, 0.25f, 0.5f, 1f, 2.5f, 7f)
            let r = radius + Tol
            from x in FacePair(r)
            from y in FacePair(r)
            from z in FacePair(r)
            select (new Box(new Vector3(x.Min, y.Min, z.Min), new Vector3(x.Max, y.Max, z.Max)), new Sphere(Vector3.Zero, radius))),
        (1, from bounds in GridBoxes
            from c in Gen.Choose(-60, 60).Select(i => i * 0.25f).Three()
            from radius in Gen.Elements(0f, 0.5f, 1f, 3f)
            select (bounds, new Sphere(new Vector3(c.Item1, c.Item2, c.Item3), radius))));

    private static Gen<Box[]> PieceBoxes { get; } =
        from n in Gen.Choose(1, 4)
        from boxes in Boxes(1).ArrayOf(n)
        select boxes;

    private static Gen<Box> Boxes(int minHalfMetres) =>
        from lo in Gen.Choose(-20, 20).Select(i => i * 0.5f).Three()
        from size in Gen.Choose(minHalfMetres, 12).Select(i => i * 0.5f).Three()
        select new Box(new Vector3(lo.Item1, lo.Item2, lo.Item3), new Vector3(lo.Item1 + size.Item1, lo.Item2 + size.Item2, lo.Item3 + size.Item3));

    private static Gen<float> Coordinate(float lo, float hi) => Gen.Elements(
        lo - Tol, MathF.BitDecrement(lo - Tol), MathF.BitIncrement(lo - Tol), lo,
        hi + Tol, MathF.BitIncrement(hi + Tol), MathF.BitDecrement(hi + Tol), hi,
        (lo + hi) / 2, lo - 5, hi + 5);

    private static Gen<(float Min, float Max)> FacePair(float r)
    {
        var face = Gen.Elements(-r - 1, MathF.BitDecrement(-r), -r, MathF.BitIncrement(-r), -r / 2, 0f, r / 2, MathF.BitDecrement(r), r, MathF.BitIncrement(r), r + 1);
        var low = Gen.Elements(-r - 1, MathF.BitDecrement(-r), -r, MathF.BitIncrement(-r));
        var high = Gen.Elements(MathF.BitDecrement(r), r, MathF.BitIncrement(r), r + 1);

        // Mostly faces around ±R on both sides (where EntirelyInside is decided), else any two faces.
        return Gen.Frequency(
            (2, Gen.Zip(low, high)),
            (1, Gen.Zip(face, face).Select(p => p.Item1 <= p.Item2 ? (p.Item1, p.Item2) : (p.Item2, p.Item1))));
    }
}
