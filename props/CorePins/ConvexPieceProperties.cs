using System.Numerics;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// ConvexPiece's corner enumeration and boundedness test (facts §5.7: the cell volume the BSP queries walk): exact
/// corners of boxes, cut boxes and tetrahedra, closed containment, and the tolerances pinned at their thresholds —
/// a corner may sit up to 1e-3 behind another plane, corners closer than 1e-4 (squared 1e-8) merge, triples with
/// |det| &lt; 1e-6 are parallel, pairs with |Nᵢ×Nⱼ|² ≤ 1e-10 give no recession direction, and a direction recedes
/// when every plane has N·u ≥ −1e-6.
/// </summary>
public sealed class ConvexPieceProperties
{
    private const float C = 0.8f; // tent roof slopes: roofs (−ε·w ± C·e₂ − H·z), C² + H² = 1
    private const float H = 0.6f;
    private const float Eps = 0.75e-6f; // tent taper: inside (1e-6 / 2, 1e-6) and below H·1e-6, so only w itself recedes

    [FixedSeedProperty(0x1D00_0040, DisplayName = "facts §5.7: a box's corners are exactly its 8 corners and its bounds are min..max, whether or not it contains the local origin")]
    public Property Box_CornersAreExactlyTheEightCorners() =>
        Prop.ForAll(Boxes.ToArbitrary(), b =>
        {
            var (min, max) = b;
            var piece = ConvexPiece.FromBox(min, max);
            var corners = Corners(min, max).ToArray();
            bool exact = piece.Vertices.Count == 8 && corners.All(piece.Vertices.Contains);
            bool bounds = piece.Bounds.Min == min && piece.Bounds.Max == max;
            bool originInside = Vector3.Min(min, Vector3.Zero) == min && Vector3.Max(max, Vector3.Zero) == max && !corners.Any(c => c.X == 0 || c.Y == 0 || c.Z == 0);
            return (exact && bounds).Classify(originInside, "origin strictly inside");
        });

    [FixedSeedProperty(0x1D00_0041, DisplayName = "facts §5.7: containment is closed: a point exactly on a face, edge or corner is inside, one float step beyond it is outside")]
    public Property Contains_IsClosed() =>
        Prop.ForAll(Probes.ToArbitrary(), t =>
        {
            var (min, max, p) = t;
            bool expected = Vector3.Clamp(p, min, max) == p;
            bool onBoundary = expected && (p.X == min.X || p.X == max.X || p.Y == min.Y || p.Y == max.Y || p.Z == min.Z || p.Z == max.Z);
            return (ConvexPiece.FromBox(min, max).Contains(p) == expected).Classify(onBoundary, "on the boundary").Classify(!expected, "one step outside or beyond");
        });

    [FixedSeedProperty(0x1D00_0042, DisplayName = "facts §5.7: a box with one corner cut off by a plane has the 7 remaining corners and the 3 cut points as corners, and not the cut-off corner")]
    public Property CutBox_HasTenCornersAndNotTheCutOne() =>
        Prop.ForAll(CutBoxes.ToArbitrary(), t =>
        {
            var (min, max, corner, cut) = t;
            var box = ConvexPiece.FromBox(min, max).Planes;
            var inward = Vector3.Normalize(((min + max) / 2) - corner);
            var step = (max - min) * cut;
            var points = new[]
            {
                corner + new Vector3(MathF.Sign(inward.X) * step.X, 0, 0),
                corner + new Vector3(0, MathF.Sign(inward.Y) * step.Y, 0),
                corner + new Vector3(0, 0, MathF.Sign(inward.Z) * step.Z),
            };
            var n = Vector3.Cross(points[1] - points[0], points[2] - points[0]);
            n = Vector3.Dot(n, inward) > 0 ? n : -n;
            var piece = new ConvexPiece(box.Append(CellPlane.Through(n, points[0])).ToArray());
            var expected = Corners(min, max).Where(c => c != corner).Concat(points).ToArray();
            bool matched = expected.All(e => piece.Vertices.Any(v => Vector3.Distance(v, e) < 1e-4f));
            return (piece.Vertices.Count == expected.Length && matched).Collect(piece.Vertices.Count);
        });

    [FixedSeedProperty(0x1D00_0043, DisplayName = "facts §5.7: a tetrahedron (four planes through the faces of four points) is accepted and its corners are the four points")]
    public Property Tetrahedron_CornersAreItsFourPoints() =>
        Prop.ForAll(Tetrahedra.ToArbitrary(), p =>
        {
            var planes = new[] { (0, 1, 2, 3), (0, 1, 3, 2), (0, 2, 3, 1), (1, 2, 3, 0) }.Select(f =>
            {
                var n = Vector3.Cross(p[f.Item2] - p[f.Item1], p[f.Item3] - p[f.Item1]);
                n = Vector3.Dot(n, p[f.Item4] - p[f.Item1]) > 0 ? n : -n;
                return new CellPlane(n, -Vector3.Dot(n, p[f.Item1]));
            }).ToArray();
            var piece = new ConvexPiece(planes);
            bool corners = piece.Vertices.Count == 4 && p.All(q => piece.Vertices.Any(v => Vector3.Distance(v, q) < 1e-3f));
            var min = p.Aggregate(Vector3.Min);
            var max = p.Aggregate(Vector3.Max);
            bool bounds = Vector3.Distance(piece.Bounds.Min, min) < 1e-3f && Vector3.Distance(piece.Bounds.Max, max) < 1e-3f;
            float det = Vector3.Dot(piece.Planes[0].Normal, Vector3.Cross(piece.Planes[1].Normal, piece.Planes[2].Normal));
            return (corners && bounds).Classify(MathF.Abs(MathF.Abs(det) - 1) > 1e-3f, "a corner's planes not orthonormal");
        });

    [FixedSeedProperty(0x1D00_0044, DisplayName = "facts §5.7: a corner up to 1e-3 (inclusive) behind another plane is kept: a box [0,s]³ cut by x ≥ δ keeps its x = 0 corners iff δ ≤ 1e-3")]
    public Property Corner_UpTo1e3BehindAPlaneIsKept() =>
        Prop.ForAll(Gen.Zip(Gen.Choose(1, 9), Gen.Elements(1e-3f, MathF.BitDecrement(1e-3f), MathF.BitIncrement(1e-3f), 5e-4f, 2e-3f, 0.25f)).ToArbitrary(), t =>
        {
            var (size, delta) = t;
            var box = ConvexPiece.FromBox(Vector3.Zero, new Vector3(size)).Planes;
            var piece = new ConvexPiece(box.Append(new CellPlane(Vector3.UnitX, -delta)).ToArray());
            bool kept = delta <= 1e-3f;
            bool corner = piece.Vertices.Contains(Vector3.Zero) == kept;
            return (corner && piece.Bounds.Min.X == (kept ? 0 : delta)).Classify(delta == 1e-3f, "exactly 1e-3 behind");
        });

    [Fact(DisplayName = "facts §5.7: two corners exactly 1e-4 apart (squared distance 1e-8 in float) are both kept; only closer ones merge")]
    public void Corners_ExactlyAtTheMergeDistanceAreBothKept()
    {
        // A thin triangular slab 0 ≤ z ≤ t whose edge y = 0, m·x = z rises diagonally: its bottom corner is the
        // origin and its top corner B ≈ (t/m, 0, t) differs in two coordinates, so |B|² can be 1e-8f exactly (a single
        // coordinate cannot: no float a has a·a == 1e-8f). B comes from the planes y = 0, m·x = z and z = t alone, so
        // a thick sibling slab (z ≥ −1) yields the same B without the merge. Walk m and t one float step at a time.
        var (m, t, b) = (from slope in new[] { 2f, 3f, 1.5f, 2.5f, 4f, 5f, 6f, 7f, 1.25f, 3.5f }
                         let t0 = MathF.Sqrt(1e-8f / (1 + (1 / (slope * slope))))
                         from k in Enumerable.Range(-60, 121)
                         let height = BitConverter.Int32BitsToSingle(BitConverter.SingleToInt32Bits(t0) + k)
                         let top = SlabTop(slope, height)
                         where Vector3.DistanceSquared(Vector3.Zero, top) == 1e-8f
                         select (slope, height, top)).First();

        Assert.True(b.X > 0 && b.Z > 0);
        var thin = new ConvexPiece(Slab(m, 0, t));
        Assert.Contains(Vector3.Zero, thin.Vertices);
        Assert.Contains(b, thin.Vertices);
        Assert.Equal(6, thin.Vertices.Count);
    }

    [Fact(DisplayName = "facts §5.7: three planes meeting at a point with |det| exactly 1e-6 still make a corner (only |det| < 1e-6 is parallel)")]
    public void Corner_FromATripleWithDetExactly1e6IsKept()
    {
        // The box [0,1]×[0,1]×[−1,1] plus x + 1e-6·z ≥ 0 (a sliver off the face x = 0 below z = 0): x = 0 and
        // x + 1e-6·z = 0 meet y = 0 and y = 1 only at (0, 0, 0) and (0, 1, 0), true corners of the piece; the box's
        // corners (0, y, −1) are 1e-6 behind the sliver and stay (within the 1e-3 tolerance), so there are 8 + 2.
        var sliver = new CellPlane(new Vector3(1, 0, 1e-6f), 0);
        var planes = ConvexPiece.FromBox(new Vector3(0, 0, -1), Vector3.One).Planes.Append(sliver).ToArray();
        var piece = new ConvexPiece(planes);
        float det = Vector3.Dot(piece.Planes[0].Normal, Vector3.Cross(piece.Planes[2].Normal, piece.Planes[6].Normal));
        Assert.Equal(1e-6f, det);
        Assert.Equal(-1e-6f, Vector3.Dot(piece.Planes[0].Normal, Vector3.Cross(piece.Planes[3].Normal, piece.Planes[6].Normal)));
        Assert.Contains(Vector3.Zero, piece.Vertices);
        Assert.Contains(Vector3.UnitY, piece.Vertices);
        Assert.Equal(10, piece.Vertices.Count);
    }

    [FixedSeedProperty(0x1D00_0045, DisplayName = "facts §5.7: a prism over the unit square whose tilted end leaves it open along ±z bounds no finite volume, whatever the plane order")]
    public Property TiltedPrism_OpenAlongZ_IsRejected() =>
        Prop.ForAll(OpenPrisms.ToArbitrary(), t =>
        {
            var (planes, up) = t;
            var message = Assert.Throws<ArgumentException>(() => new ConvexPiece(planes)).Message;
            return message.Contains("bound no finite volume", StringComparison.Ordinal).Classify(up, "open towards +z").Classify(!up, "open towards −z");
        });

    [Fact(DisplayName = "facts §5.7: a direction recedes iff every plane has N·u ≥ −1e-6 (inclusive): a wedge whose roof tapers by exactly 1e-6 is rejected, by one float more is accepted")]
    public void Wedge_TaperingByExactly1e6_IsUnbounded()
    {
        static CellPlane[] Wedge(float slope) =>
        [
            new(Vector3.UnitX, 0), new(Vector3.UnitY, 0), new(-Vector3.UnitY, 1), new(Vector3.UnitZ, 0), new(new Vector3(-slope, 0, -1), 1),
        ];

        // Normalising (−slope, 0, −1) leaves it as it is, so the roof's N·x is exactly −slope.
        Assert.Equal(-1e-6f, Vector3.Normalize(Wedge(1e-6f)[4].Normal).X);
        Assert.Contains("bound no finite volume", Assert.Throws<ArgumentException>(() => new ConvexPiece(Wedge(1e-6f))).Message);
        Assert.True(new ConvexPiece(Wedge(MathF.BitIncrement(1e-6f))).Vertices.Count >= 4);
    }

    [Fact(DisplayName = "facts §5.7: a flat tent that closes ~1e6 m away (every plane within 1e-6 of parallel to its axis) counts as unbounded when its axis is a plane normal or a receding Nᵢ×Nⱼ")]
    public void Tent_WhoseAxisIsANormalOrACrossProduct_IsRejected()
    {
        // The axis w = +x is only a plane's normal (the base x ≥ 0): the cross products of the floor, ceiling and roofs
        // are all blocked (by ≥ 1.5e-6), so only the normals test sees it.
        var axisBase = Tent(Vector3.UnitX, Vector3.UnitX);
        Assert.Contains("bound no finite volume", Assert.Throws<ArgumentException>(() => new ConvexPiece(axisBase)).Message);

        // A slanted base and a second floor tilted by 1e-4 about w: now w is only ±(floor × floor₂) = ±(floor₂ × ceiling),
        // and both i<j cross products point along −w.
        var slanted = Vector3.Normalize(new Vector3(1, 0.3f, 0.2f));
        var crossed = Tent(Vector3.UnitX, slanted, new CellPlane(new Vector3(0, 1e-4f, 1), 0));
        Assert.True(Vector3.Cross(crossed[0].Normal, crossed[1].Normal).X < 0);
        Assert.Contains("bound no finite volume", Assert.Throws<ArgumentException>(() => new ConvexPiece(crossed)).Message);

        // Without the second floor the same tent is accepted: its near-receding axis is no normal and no cross product.
        Assert.True(new ConvexPiece(Tent(Vector3.UnitX, slanted)).Vertices.Count >= 4);
    }

    [Fact(DisplayName = "facts §5.7: two planes with |N₁×N₂|² exactly 1e-10 count as parallel (their cross product is no recession direction); one float more and it is")]
    public void Tent_CrossProductAtExactly1e10_IsNoRecessionDirection()
    {
        var atThreshold = FloorPair(1e-10f);
        var above = FloorPair(MathF.BitIncrement(1e-10f));
        Assert.Equal(1e-10f, Vector3.Cross(Vector3.UnitZ, Vector3.Normalize(atThreshold)).LengthSquared());
        Assert.Equal(MathF.BitIncrement(1e-10f), Vector3.Cross(Vector3.UnitZ, Vector3.Normalize(above)).LengthSquared());

        static CellPlane[] Rotated(Vector3 floor2)
        {
            var w = Vector3.Normalize(-Vector3.Cross(Vector3.UnitZ, floor2)); // the receding axis: floor × floor₂ points along −w
            var slanted = Vector3.Normalize(w + (0.3f * new Vector3(-w.Y, w.X, 0)) + (0.2f * Vector3.UnitZ));
            return Tent(w, slanted, new CellPlane(floor2, 0));
        }

        Assert.True(new ConvexPiece(Rotated(atThreshold)).Vertices.Count >= 4);
        Assert.Contains("bound no finite volume", Assert.Throws<ArgumentException>(() => new ConvexPiece(Rotated(above))).Message);
    }

    [FixedSeedProperty(0x1D00_0046, DisplayName = "facts §5.7: a yawed box up to 5.6 km from the local origin has exactly its 8 corners, each found once (a corner met by a reordered plane triple is no new corner)")]
    public Property FarYawedBox_HasEachCornerOnce() =>
        Prop.ForAll(FarYawedBoxes.ToArbitrary(), t =>
        {
            var (centre, half, yaw) = t;
            var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw);
            var axes = new[] { Vector3.Transform(Vector3.UnitX, rotation), Vector3.Transform(Vector3.UnitY, rotation), Vector3.UnitZ };
            var planes = axes.SelectMany((a, k) => new[] { CellPlane.Through(a, centre - (a * half[k])), CellPlane.Through(-a, centre + (a * half[k])) }).ToArray();
            var piece = new ConvexPiece(planes);
            var corners = Enumerable.Range(0, 8).Select(c => centre
                + (axes[0] * half.X * ((c & 1) == 0 ? -1 : 1))
                + (axes[1] * half.Y * ((c & 2) == 0 ? -1 : 1))
                + (axes[2] * half.Z * ((c & 4) == 0 ? -1 : 1))).ToArray();
            float tolerance = 1e-6f * centre.Length() * 8 + 1e-3f; // a few float steps at this distance
            bool each = corners.All(c => piece.Vertices.Count(v => Vector3.Distance(v, c) < tolerance) == 1);
            return (piece.Vertices.Count == 8 && each).Label($"{piece.Vertices.Count} corners").Classify(centre.Length() > 1024, "over 1 km out (float steps over 1e-4)");
        });

    [FixedSeedProperty(0x1D00_0047, DisplayName = "facts §5.7: a thin tilted wedge (a roof rising by m·y over a floor, m = 0.03–0.3) has 6 corners, each found once, though its sharp edge's corners come from ill-conditioned plane triples")]
    public Property ThinWedge_HasEachCornerOnce() =>
        Prop.ForAll(ThinWedges.ToArbitrary(), t =>
        {
            var (at, length, width, slope, turn) = t;
            var rotation = Quaternion.CreateFromAxisAngle(Vector3.Normalize(new Vector3(0.3f, 0.5f, 0.8f)), turn);
            CellPlane Plane(Vector3 inward, Vector3 through) => CellPlane.Through(Vector3.Transform(inward, rotation), at + Vector3.Transform(through, rotation));

            // In the wedge's own frame: x ∈ [0, length], y ≤ width, z ≥ 0 (floor), z ≤ m·y (roof); the floor and the
            // roof meet along the x axis. Listed so that they are neighbours after an x plane: the sharp-edge corners
            // (x plane, floor, roof) have |det| ≈ m, so rounding in the intersection is amplified by 1/m, and a
            // tilted frame gives every plane three non-zero normal components.
            var piece = new ConvexPiece(
            [
                Plane(Vector3.UnitX, Vector3.Zero),
                Plane(Vector3.UnitZ, Vector3.Zero),
                Plane(new Vector3(0, slope, -1), Vector3.Zero),
                Plane(-Vector3.UnitX, new Vector3(length, 0, 0)),
                Plane(-Vector3.UnitY, new Vector3(0, width, 0)),
            ]);
            var corners = new[] { 0f, length }.SelectMany(x => new[] { new Vector3(x, 0, 0), new Vector3(x, width, 0), new Vector3(x, width, slope * width) }).ToArray();
            var local = piece.Vertices.Select(v => Vector3.Transform(v - at, Quaternion.Conjugate(rotation))).ToArray();
            float thickness = slope * width; // the far end's two corners are this far apart, in z only
            bool Near(Vector3 v, Vector3 c) => MathF.Abs(v.X - c.X) < 0.05f && MathF.Abs(v.Y - c.Y) < 0.05f && MathF.Abs(v.Z - c.Z) < thickness / 3;
            bool each = corners.All(c => local.Count(v => Near(v, c)) == 1);
            return (piece.Vertices.Count == 6 && each).Label($"{piece.Vertices.Count} corners: {string.Join(" ", local)}").Collect(slope);
        });

    // Thin wedges 2–20 m long and wide, tilted, their sharp edge anywhere within 100 m of the local origin. Slopes
    // below ~0.01 lose a sharp-edge corner (its error, about |D|·ulp / m, passes the 1e-3 tolerance): docs/indoor.md.
    private static Gen<(Vector3 At, float Length, float Width, float Slope, float Turn)> ThinWedges { get; } =
        from x in Gen.Choose(-1000, 1000)
        from y in Gen.Choose(-1000, 1000)
        from z in Gen.Choose(-1000, 1000)
        from length in Gen.Choose(2, 20)
        from width in Gen.Choose(2, 20)
        from slope in Gen.Elements(0.03f, 0.1f, 0.3f)
        from turn in Gen.Elements(0.4f, 1.3f, 2.2f, -0.7f)
        select (new Vector3(x * 0.1037f, y * 0.0991f, z * 0.1013f), (float)length, (float)width, slope, turn);

    // Yawed boxes 1–10 m a side whose centre is up to 5.6 km from the local origin (further out the fixed 1e-3 corner tolerance is below float resolution: docs/indoor.md), where float steps exceed 1e-4.
    private static Gen<(Vector3 Centre, Vector3 Half, float Yaw)> FarYawedBoxes { get; } =
        from x in Gen.Choose(-4000, 4000)
        from y in Gen.Choose(-4000, 4000)
        from z in Gen.Choose(-50, 50)
        from half in Gen.Choose(1, 10).Three()
        from yaw in Gen.Elements(0.3f, 0.7f, 1.1f, 2.5f, -0.9f)
        select (new Vector3(x + 0.37f, y + 0.61f, z), new Vector3(half.Item1, half.Item2, half.Item3) * 0.5f, yaw);

    private static Gen<(Vector3 Min, Vector3 Max)> Boxes { get; } =
        from lo in Gen.Choose(-12, 4).Select(i => i * 0.5f).Three()
        from size in Gen.Choose(1, 16).Select(i => i * 0.5f).Three()
        let min = new Vector3(lo.Item1, lo.Item2, lo.Item3)
        select (min, min + new Vector3(size.Item1, size.Item2, size.Item3));

    private static Gen<(Vector3 Min, Vector3 Max, Vector3 P)> Probes { get; } =
        from box in Boxes
        from pick in Gen.Choose(0, 4).Three()
        let c = new[] { pick.Item1, pick.Item2, pick.Item3 }.Select((k, axis) => Coordinate(box.Min[axis], box.Max[axis], k)).ToArray()
        select (box.Min, box.Max, new Vector3(c[0], c[1], c[2]));

    private static Gen<(Vector3 Min, Vector3 Max, Vector3 Corner, Vector3 Cut)> CutBoxes { get; } =
        from box in Boxes
        from which in Gen.Choose(0, 7)
        from cut in Gen.Elements(0.25f, 0.5f, 0.75f).Three()
        select (box.Min, box.Max, Corners(box.Min, box.Max).ElementAt(which), new Vector3(cut.Item1, cut.Item2, cut.Item3));

    // P0 plus the columns of a lower-triangular integer matrix with a positive diagonal: never degenerate, and its
    // faces are generally not orthogonal (so a corner's plane determinant is not ±1).
    private static Gen<Vector3[]> Tetrahedra { get; } =
        from p0 in Gen.Choose(-8, 8).Three()
        from diagonal in Gen.Choose(1, 6).Three()
        from shear in Gen.Choose(-4, 4).Three()
        let o = new Vector3(p0.Item1, p0.Item2, p0.Item3)
        select new[]
        {
            o,
            o + new Vector3(diagonal.Item1, shear.Item1, shear.Item2),
            o + new Vector3(0, diagonal.Item2, shear.Item3),
            o + new Vector3(0, 0, diagonal.Item3),
        };

    // x, y ∈ [0,1] and an end tilted by a slope, open towards +z (z ≥ slope·x) or −z (z ≤ slope·x), shuffled: no
    // plane normal recedes, only the side planes' cross product ±z exposes it.
    private static Gen<(CellPlane[] Planes, bool Up)> OpenPrisms { get; } =
        from slope in Gen.Elements(0.1f, 0.5f, -0.3f, 2f)
        from up in Gen.Elements(true, false)
        from order in Gen.Shuffle(Enumerable.Range(0, 5).ToArray())
        let end = up ? new CellPlane(new Vector3(-slope, 0, 1), 0) : new CellPlane(new Vector3(slope, 0, -1), 0)
        let planes = new[] { new CellPlane(Vector3.UnitX, 0), new CellPlane(-Vector3.UnitX, 1), new CellPlane(Vector3.UnitY, 0), new CellPlane(-Vector3.UnitY, 1), end }
        select (order.Select(i => planes[i]).ToArray(), up);

    private static IEnumerable<Vector3> Corners(Vector3 min, Vector3 max) => Enumerable.Range(0, 8).Select(new Box(min, max).Corner);

    private static float Coordinate(float min, float max, int k) => k switch
    {
        0 => min,
        1 => max,
        2 => (min + max) / 2,
        3 => MathF.BitDecrement(min),
        _ => MathF.BitIncrement(max),
    };

    // The slab −bottom ≤ z ≤ t over the triangle y ≥ 0, m·x ≥ z, x + y + 10z ≤ 1.
    private static CellPlane[] Slab(float m, float bottom, float t) =>
    [
        new(Vector3.UnitZ, bottom), new(Vector3.UnitY, 0), new(new Vector3(m, 0, -1), 0), new(new Vector3(-1, -1, -10), 1), new(-Vector3.UnitZ, t),
    ];

    private static Vector3 SlabTop(float m, float t)
    {
        var thick = new ConvexPiece(Slab(m, 1, t));
        return thick.Vertices.Where(v => v.Z > 0).MinBy(v => v.X + Math.Abs(v.Y));
    }

    // A floor-like unit normal (r, s, 1) (|(r, s)|² ≪ float's step at 1, so normalising leaves it as it is) whose cross
    // product with +z has squared length exactly target, found by walking r and s one float step at a time.
    private static Vector3 FloorPair(float target)
    {
        float s0 = MathF.Sqrt(target / 2);
        for (int i = 0; i < 200; i++)
        {
            float r = s0 + (i * (MathF.BitIncrement(s0) - s0));
            for (int j = 0; j < 200; j++)
            {
                var n = new Vector3(r, s0 - (j * (MathF.BitIncrement(s0) - s0)), 1);
                if (Vector3.Cross(Vector3.UnitZ, Vector3.Normalize(n)).LengthSquared() == target)
                {
                    return n;
                }
            }
        }

        throw new InvalidOperationException("no floor pair at the target");
    }

    // A tent along the unit horizontal axis w: floor z ≥ 0, extra floors, ceiling z ≤ 0.5, two roofs tapering by
    // Eps towards +w (±C·e₂ − H·z − Eps·w + 1 ≥ 0), and a base through the origin. The roofs close ~1e6 m away, so
    // the piece is bounded, but every plane has N·w ≥ −1e-6; each cross product other than ±w is blocked by ≥ 1.5e-6.
    private static CellPlane[] Tent(Vector3 w, Vector3 baseNormal, params CellPlane[] floors)
    {
        var e2 = new Vector3(-w.Y, w.X, 0);
        return
        [
            new(Vector3.UnitZ, 0), .. floors, new(-Vector3.UnitZ, 0.5f),
            new((-Eps * w) + (C * e2) - (H * Vector3.UnitZ), 1), new((-Eps * w) - (C * e2) - (H * Vector3.UnitZ), 1),
            new(baseNormal, 0),
        ];
    }
}
