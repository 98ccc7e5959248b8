using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Mutation;

/// <summary>
/// The indoor core where the 2026-12-01 mutation run found no test: the geometry constructors' validation, the AABB
/// box test, intersect_box's in-plane corners, the ACE preset, and a parts-transit neighbour that is not loaded.
/// </summary>
public sealed class IndoorMutationTests
{
    private static readonly CellId Room0 = new(0xA9B40100);
    private static readonly CellId Room1 = new(0xA9B40101);
    private static readonly CellId Owner = new(0xA9B40013);

    [Fact(DisplayName = "facts §5.7: a convex piece needs four valid planes bounding a finite volume; anything else is rejected with the reason")]
    public void ConvexPiece_RejectsWhatBoundsNoVolume()
    {
        var x = new CellPlane(Vector3.UnitX, 0);
        var y = new CellPlane(Vector3.UnitY, 0);
        var z = new CellPlane(Vector3.UnitZ, 0);
        var top = new CellPlane(-Vector3.UnitZ, 1);
        Assert.Contains("at least 4 planes", Rejects([x, y, z]));
        Assert.Contains("plane 2 is degenerate", Rejects([x, y, new CellPlane(Vector3.Zero, 1), top]));
        Assert.Contains("plane 3 is degenerate", Rejects([x, y, z, new CellPlane(-Vector3.UnitZ, float.NaN)]));

        // Four corners (z = 0 and 1 on the line x + y = 1) but open towards +x+y: the unbounded-cone test must see it.
        var wedge = new CellPlane(Vector3.Normalize(new Vector3(1, 1, 0)), -MathF.Sqrt(0.5f));
        Assert.Contains("bound no finite volume", Rejects([x, y, z, top, wedge]));

        // Five planes that do bound a volume (a box cut by the same slanted plane, flipped) are accepted.
        var cut = new ConvexPiece([x, y, z, top, new CellPlane(-wedge.Normal, 2 * MathF.Sqrt(0.5f))]);
        Assert.True(cut.Contains(new Vector3(0.5f, 0.5f, 0.5f)));
    }

    [Fact(DisplayName = "facts §5.7: a plane is usable iff its normal's three components and D are finite and |N|² > 1e-12 (an infinite component on any one axis is refused)")]
    public void CellPlane_IsValidNeedsEveryComponentFiniteAndANonZeroNormal()
    {
        foreach (int axis in new[] { 0, 1, 2 })
        {
            var n = Vector3.UnitX;
            n[axis] = float.PositiveInfinity;
            Assert.False(new CellPlane(n, 0).IsValid, $"infinite normal component {axis}");
            n[axis] = float.NaN;
            Assert.False(new CellPlane(n, 0).IsValid, $"NaN normal component {axis}");
        }

        Assert.False(new CellPlane(Vector3.UnitZ, float.NegativeInfinity).IsValid);

        // The smallest usable normal: |N|² one step above 1e-12 is valid, exactly 1e-12 is not.
        float x = MathF.Sqrt(1e-12f);
        while (x * x > 1e-12f)
        {
            x = MathF.BitDecrement(x);
        }

        while (x * x < 1e-12f)
        {
            x = MathF.BitIncrement(x);
        }

        Assert.Equal(1e-12f, x * x);
        Assert.False(new CellPlane(new Vector3(x, 0, 0), 0).IsValid);
        Assert.True(new CellPlane(new Vector3(MathF.BitIncrement(x), 0, 0), 0).IsValid);
    }

    [FixedSeedProperty(0x1D00_0003, DisplayName = "facts §5.7: a piece normalises its planes: scaling a plane's (N, D) by k > 0 leaves the planes, corners, bounds and containment unchanged")]
    public Property ConvexPiece_NormalisesItsPlanes() =>
        Prop.ForAll(ScaledPieces.ToArbitrary(), t =>
        {
            var (unit, scales, probe) = t;
            var scaled = new ConvexPiece(unit.Select((p, i) => new CellPlane(p.Normal * scales[i], p.D * scales[i])).ToArray());
            var reference = new ConvexPiece(unit);
            bool planes = scaled.Planes.Zip(unit).All(z => Vector3.Distance(z.First.Normal, z.Second.Normal) < 1e-5f && MathF.Abs(z.First.D - z.Second.D) < 1e-4f);
            bool bounds = Vector3.Distance(scaled.Bounds.Min, reference.Bounds.Min) < 1e-3f && Vector3.Distance(scaled.Bounds.Max, reference.Bounds.Max) < 1e-3f;
            bool inside = reference.Contains(probe);
            return (planes && bounds && scaled.Vertices.Count == reference.Vertices.Count && scaled.Contains(probe) == inside).Classify(inside, "probe inside");
        });

    [Fact(DisplayName = "facts §5.7: a cell volume (BSP or AABB) needs at least one piece; an env cell needs an env cell id")]
    public void CellVolumes_RejectNoPieces()
    {
        Assert.Contains("at least one piece", Assert.Throws<ArgumentException>(() => new CellBsp([])).Message);
        Assert.Contains("at least one piece", Assert.Throws<ArgumentException>(() => new CellAabb(Array.Empty<ConvexPiece>())).Message);
        var volume = new CellAabb([ConvexPiece.FromBox(Vector3.Zero, Vector3.One)]);
        Assert.Contains("is not an env cell id", Assert.Throws<ArgumentException>(() => new EnvCell(Owner, Frame.Identity, volume, [], [])).Message);
        Assert.Equal(Room0, new EnvCell(Room0, Frame.Identity, volume, [], []).Id);
    }

    [Fact(DisplayName = "facts §5.3: a scene rejects two env cells with one id and two buildings attached to one land cell (a SortCell holds one)")]
    public void CellScene_RejectsDuplicates()
    {
        var block = Room0.Landblock;
        var volume = new CellAabb([ConvexPiece.FromBox(Vector3.Zero, Vector3.One)]);
        var room = new EnvCell(Room0, Frame.Identity, volume, [], []);
        var duplicate = Assert.Throws<ArgumentException>(() => new CellScene([block], [room, room], []));
        Assert.Contains("duplicate env cell", duplicate.Message);

        var a = new Building(block, new Vector3(50, 50, 0), []);
        var b = new Building(block, new Vector3(51, 52, 0), []);
        var twice = Assert.Throws<ArgumentException>(() => new CellScene([block], [], [a, b]));
        Assert.Contains("two buildings attached to land cell", twice.Message);

        var apart = new CellScene([block], [], [a, b with { Origin = new Vector3(80, 52, 0) }]);
        Assert.Equal(2, apart.Buildings.Count);
    }

    [FixedSeedProperty(0x1D00_0001, DisplayName = "seed point_in_cell (ACME): the AABB volume's box test is interval overlap on each axis with the 0.01 tolerance, inclusive at the tolerance")]
    public Property CellAabb_BoxIntersectsIsToleratedOverlap() =>
        Prop.ForAll(AabbCases.ToArbitrary(), t =>
        {
            var (bounds, query) = t;
            const float tol = 0.01f;
            bool Overlap(float qMin, float qMax, float bMin, float bMax) => qMin <= bMax + tol && qMax >= bMin - tol;
            bool expected = Overlap(query.Min.X, query.Max.X, bounds.Min.X, bounds.Max.X)
                && Overlap(query.Min.Y, query.Max.Y, bounds.Min.Y, bounds.Max.Y)
                && Overlap(query.Min.Z, query.Max.Z, bounds.Min.Z, bounds.Max.Z);
            bool actual = new CellAabb(bounds).BoxIntersects(query);
            return (actual == expected).Classify(expected, "overlapping").Classify(!expected, "apart");
        });

    [FixedSeedProperty(0x1D00_0002, DisplayName = "facts §5.7 (PE:49-72): intersect_box is the common side of all eight corners (biased by +EPS) when d(Min) is outside ±EPS; any corner in the plane or across makes it Crossing")]
    public Property IntersectBox_MatchesTheCornerDefinition() =>
        Prop.ForAll(SideCases.ToArbitrary(), t =>
        {
            var (plane, box) = t;
            const float eps = LandDefs.Epsilon;
            float dMin = plane.Distance(box.Min);
            var corners = Enumerable.Range(0, 8).Select(box.Corner).Select(c => plane.Distance(c) + eps).ToArray();
            var expected = dMin >= -eps && dMin <= eps ? Sidedness.Crossing
                : dMin > eps && corners.All(d => d > eps) ? Sidedness.Positive
                : dMin < -eps && corners.All(d => d < -eps) ? Sidedness.Negative
                : Sidedness.Crossing;
            bool closeCorner = corners.Any(d => d >= -eps && d <= eps);
            return (BoxSide.Of(plane, box) == expected).Collect(expected).Classify(closeCorner, "a corner within EPS");
        });

    [Fact(DisplayName = "facts §7 #6–#14, #9: IndoorFidelity.Ace switches on every documented ACE difference and nothing that is not ACE's (ReframeTransit)")]
    public void IndoorFidelity_AcePreset()
    {
        var ace = IndoorFidelity.Ace;
        Assert.Equal(
            [true, true, true, true, true, true, true, true, false, true, true],
            [ace.AceKeepsStaleCells, ace.AceEarlyReturn, ace.AceFilterOutsideGuard, ace.AceNeighbourViaVisibleCells, ace.AceLoadHintLowKey, ace.AceOutsideByCellId, ace.AceNoPortalGuard, ace.DropUnloadedLandCells, ace.ReframeTransit, ace.AceTransitionFilters, ace.AceBoxSidePairing]);
        Assert.True(ace.Outdoor.DropUnloadedCells);
        Assert.Equal(default, IndoorFidelity.Retail);
    }

    [Fact(DisplayName = "facts §5.2, §7 #11: by parts, a door to a cell the scene does not hold is a not-loaded hint under its full id (ACE: the bare 16-bit id), and transit stops at that door")]
    public void PartsTransit_UnloadedNeighbourIsAHint()
    {
        var cottage = SceneBuild.Build(SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, false, false)));
        var room0 = cottage.GetEnvCell(Room0)!;
        var alone = new CellScene([Room0.Landblock], [room0], cottage.Buildings.Values);
        var part = new Part(Owner, new Frame(new Vector3(55.9f, 53, 1), Quaternion.Identity), new Box(new Vector3(-0.2f), new Vector3(0.2f)), 0.5f, false);

        var array = new CellArray();
        EnvTransitParts.FindTransitCells(array, alone, room0, [part], IndoorFidelity.Retail);
        Assert.Equal([new CellEntry(Room1, false)], CellArrays.Entries(array));

        array.Reset();
        EnvTransitParts.FindTransitCells(array, alone, room0, [part], new IndoorFidelity(AceLoadHintLowKey: true));
        Assert.Equal([new CellEntry(new CellId(Room1.Low), false)], CellArrays.Entries(array));

        // Loaded, but ACE looks the neighbour up in VisibleCells only: a room not listed there is a hint too.
        array.Reset();
        var blind = new EnvCell(Room0, room0.Frame, room0.Volume, room0.Portals.ToArray(), []);
        EnvTransitParts.FindTransitCells(array, cottage, blind, [part], new IndoorFidelity(AceNeighbourViaVisibleCells: true));
        Assert.Equal([new CellEntry(Room1, false)], CellArrays.Entries(array));
        array.Reset();
        EnvTransitParts.FindTransitCells(array, cottage, blind, [part], IndoorFidelity.Retail);
        Assert.Equal([new CellEntry(Room1, true)], CellArrays.Entries(array));
    }

    // Bounds and query boxes whose faces often sit exactly at bound ± tolerance, where <= and < differ.
    private static Gen<(Box Bounds, Box Query)> AabbCases { get; } =
        from lo in Gen.Choose(-20, 20).Select(i => i * 0.5f).Three()
        from size in Gen.Choose(1, 12).Select(i => i * 0.5f).Three()
        let bounds = new Box(new Vector3(lo.Item1, lo.Item2, lo.Item3), new Vector3(lo.Item1 + size.Item1, lo.Item2 + size.Item2, lo.Item3 + size.Item3))
        from qx in Interval(bounds.Min.X, bounds.Max.X)
        from qy in Interval(bounds.Min.Y, bounds.Max.Y)
        from qz in Interval(bounds.Min.Z, bounds.Max.Z)
        select (bounds, new Box(new Vector3(qx.Min, qy.Min, qz.Min), new Vector3(qx.Max, qy.Max, qz.Max)));

    // An axis plane through a grid offset and boxes whose corners are often within EPS of it (or exactly on it).
    private static Gen<(CellPlane Plane, Box Box)> SideCases { get; } =
        from axis in Gen.Choose(0, 5)
        from offset in Gen.Choose(-4, 4)
        let normal = (axis % 3 == 0 ? Vector3.UnitX : axis % 3 == 1 ? Vector3.UnitY : Vector3.UnitZ) * (axis < 3 ? 1 : -1)
        let plane = new CellPlane(normal, offset)
        from lo in Near(-offset * (axis < 3 ? 1 : -1)).Three()
        from size in Gen.Elements(0f, 0.0001f, 0.0002f, 0.0003f, 0.5f, 1f, 3f).Three()
        select (plane, new Box(new Vector3(lo.Item1, lo.Item2, lo.Item3), new Vector3(lo.Item1 + size.Item1, lo.Item2 + size.Item2, lo.Item3 + size.Item3)));

    private static Gen<(float Min, float Max)> Interval(float bMin, float bMax)
    {
        const float tol = 0.01f;
        var edge = Gen.Elements(bMin - tol, bMax + tol, bMin, bMax, bMin - tol - 0.005f, bMax + tol + 0.005f, bMin - 3, bMax + 3);
        return Gen.Zip(edge, edge).Select(p => p.Item1 <= p.Item2 ? (p.Item1, p.Item2) : (p.Item2, p.Item1));
    }

    // Unit-normal boxes (some cut by a slanted plane), a positive scale per plane, and a probe point well clear of
    // every plane (so containment does not hinge on rounding).
    private static Gen<(CellPlane[] Unit, float[] Scales, Vector3 Probe)> ScaledPieces { get; } =
        from lo in Gen.Choose(-10, 10).Three()
        from size in Gen.Choose(2, 8).Three()
        from cut in Gen.Elements(false, true)
        from scales in Gen.Elements(0.25f, 1f, 2f, 3.7f, 40f).ArrayOf(7)
        from probe in Gen.Choose(-4, 16).Select(i => (i * 0.5f) + 0.3f).Three()
        let min = new Vector3(lo.Item1, lo.Item2, lo.Item3)
        let max = min + new Vector3(size.Item1, size.Item2, size.Item3)
        let box = ConvexPiece.FromBox(min, max).Planes
        let slant = CellPlane.Through(new Vector3(-1, -1, 0), max - new Vector3(0.5f, 0.5f, 0))
        select ((cut ? box.Append(slant) : box).ToArray(), scales, min + new Vector3(probe.Item1, probe.Item2, probe.Item3));

    private static Gen<float> Near(float onPlane) => Gen.Frequency(
        (3, Gen.Elements(0f, 0.0001f, -0.0001f, 0.0002f, -0.0002f, 0.0003f, -0.0003f, -0.0004f, -1f, 1f, -2f).Select(d => onPlane + d)),
        (1, Gen.Choose(-300, 300).Select(i => i * 0.01f)));

    private static string Rejects(CellPlane[] planes) => Assert.Throws<ArgumentException>(() => new ConvexPiece(planes)).Message;
}
