using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// sphere_intersects_cell_bsp on one box piece (facts §5.7): the chain ends in a leaf, which always straddles, so the
/// answer is Outside iff some plane has d ≤ −R (R = r + 0.01), else PartiallyInside; never EntirelyInside.
/// </summary>
public sealed class CellBspSphereProperties
{
    [FixedSeedProperty(0x1D00_0030, DisplayName = "facts §5.7 (BN:219-240): a BSP chain ending in a leaf answers Outside iff some plane has d ≤ −R exactly, else PartiallyInside")]
    public Property SphereIntersects_IsOutsideIffSomePlaneIsAtLeastRBehind() =>
        Prop.ForAll(Cases.ToArbitrary(), t =>
        {
            var (box, radius) = t;
            float r = radius + 0.01f;

            // The centre is the origin, so each face's signed distance (inside positive) is exactly −min or max.
            var d = new[] { -box.Min.X, box.Max.X, -box.Min.Y, box.Max.Y, -box.Min.Z, box.Max.Z };
            var expected = d.Any(x => x <= -r) ? BoundingType.Outside : BoundingType.PartiallyInside;
            var actual = new CellBsp([ConvexPiece.FromBox(box.Min, box.Max)]).SphereIntersects(new Sphere(Vector3.Zero, radius));
            return (actual == expected).Collect(expected).Classify(d.Any(x => x == -r), "a face exactly R behind the centre");
        });

    // Faces at exactly ±R, one ULP either side, or well clear; each axis keeps max − min ≥ 5 mm (thinner pieces are
    // refused as bounding no volume).
    private static Gen<(Box Box, float Radius)> Cases { get; } =
        from radius in Gen.Elements(0f, 0.25f, 0.5f, 1f, 2.5f)
        let r = radius + 0.01f
        from x in Axis(r)
        from y in Axis(r)
        from z in Axis(r)
        select (new Box(new Vector3(x.Min, y.Min, z.Min), new Vector3(x.Max, y.Max, z.Max)), radius);

    private static Gen<(float Min, float Max)> Axis(float r)
    {
        var face = Gen.Elements(-r - 1, MathF.BitDecrement(-r), -r, MathF.BitIncrement(-r), 0f, MathF.BitDecrement(r), r, MathF.BitIncrement(r), r + 1);
        return Gen.Frequency(
            (2, Gen.Zip(Gen.Elements(-r - 1, -r / 2, 0f), Gen.Elements(r / 2, r + 1)).Select(p => (p.Item1, p.Item2))),
            (1, Gen.Zip(face, face).Where(p => MathF.Abs(p.Item1 - p.Item2) >= 0.005f).Select(p => p.Item1 < p.Item2 ? (p.Item1, p.Item2) : (p.Item2, p.Item1))));
    }
}
