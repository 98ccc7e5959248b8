using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Support;
using AcPhys.Spec.Cases;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Core;

/// <summary>
/// Land-cell containment as retail computes it (facts §5.5, §5.6): float32 point_in_poly2D over the two terrain
/// triangles. Issue #29: the reference used the exact closed square; these pin where the two agree and where not.
/// </summary>
public sealed class LandCellContainment
{
    private static readonly Gen<int> Offsets = Gen.Elements(-8, -4, -2, -1, 0, 1, 2, 4, 8);

    // A point near a cell's edges or corners: each coordinate is a line of the cell (or a point between) moved by ulps
    // or by a few tenths of a micrometre.
    private static Gen<(CellId Cell, Vector2 P)> NearEdges =>
        Gen.Zip(Gen.Zip(Gen.Choose(0, 254), Gen.Choose(0, 254)), Gen.Zip(Gen.Choose(1, 64), Gen.Zip(Coordinate, Coordinate)))
            .Select(t =>
            {
                var cell = new CellId((byte)t.Item1.Item1, (byte)t.Item1.Item2, (ushort)t.Item2.Item1);
                int idx = cell.Low - 1;
                var (fx, fy) = t.Item2.Item2;
                return (cell, new Vector2(fx(24f * (idx >> 3)), fy(24f * (idx & 7))));
            });

    [Fact(DisplayName = "facts §5.6: the s ≥ 2³¹ test equals s·2.3283064e−10 ≥ 0.5 on every cell of the map")]
    public void DiagonalRuleMatchesTheFactsFormulaEverywhere()
    {
        int differ = 0;
        for (int gx = 0; gx < 2040; gx++)
        {
            for (int gy = 0; gy < 2040; gy++)
            {
                uint s = unchecked(((uint)gy * ((214614067u * (uint)gx) + 1813693831u)) - (1109124029u * (uint)gx) - 1369149221u);
                bool facts = s * 2.3283064e-10 >= 0.5;
                differ += facts == TerrainTriangles.CutsSouthWestToNorthEast(gx, gy) ? 0 : 1;
            }
        }

        Assert.Equal(0, differ);
    }

    [CiProperty(MaxTest = 5000, DisplayName = "facts §5.5: every point of a land cell's closed square is inside one of its terrain triangles")]
    public Property ClosedSquareIsContained() =>
        Prop.ForAll(NearEdges.ToArbitrary(), t =>
        {
            bool inSquare = InSquare(t.Cell, t.P, 0);
            return (!inSquare || TerrainTriangles.Contains(t.Cell, new Vector3(t.P, 0.5f)))
                .Classify(inSquare, "in the square")
                .Classify(!inSquare, "outside the square");
        });

    [CiProperty(MaxTest = 5000, DisplayName = "facts §5.5: the triangles accept no point outside the square but within rounding of a corner (less than 1 µm)")]
    public Property TrianglesStayWithinRoundingOfTheSquare() =>
        Prop.ForAll(NearEdges.ToArbitrary(), t =>
        {
            bool contained = TerrainTriangles.Contains(t.Cell, new Vector3(t.P, 0.5f));
            bool sliver = contained && !InSquare(t.Cell, t.P, 0);
            return (!contained || InSquare(t.Cell, t.P, 1e-6f))
                .Classify(sliver, "corner sliver (outside the square, inside a triangle)")
                .Classify(contained && !sliver, "inside the square")
                .Classify(!contained, "outside");
        });

    [Theory(DisplayName = "facts §6.17: a non-finite point is in no terrain triangle (the reference's hardening; retail's crosses would be NaN)")]
    [InlineData(float.NaN, 12f)]
    [InlineData(12f, float.NaN)]
    [InlineData(float.PositiveInfinity, 12f)]
    [InlineData(12f, float.NegativeInfinity)]
    public void NonFinitePointIsInNoTriangle(float x, float y)
    {
        var cell = FirstCell(cut: true, cx: 0, cy: 0);
        Assert.False(TerrainTriangles.Contains(cell, new Vector3(x, y, 0.5f)));
        Assert.True(TerrainTriangles.Contains(cell, new Vector3(12f, 12f, 0.5f))); // the same cell holds its centre
    }

    [Fact(DisplayName = "facts §5.5: a corner sliver exists — 1e-7 m west of a south-west corner the SW–NE triangle accepts the point")]
    public void TheSliverAtASouthWestCorner()
    {
        // Cell (0, 1) of a block whose diagonal is SW–NE: polygon 0 = (SW, SE, NE) has no west edge, and
        // p.x − 24 rounds to −24 in float32, so its diagonal cross is 0 and nothing rejects the point.
        var cell = FirstCell(cut: true, cx: 0, cy: 1);
        var p = new Vector3(-1e-7f, 24f, 0.5f);
        Assert.True(TerrainTriangles.Contains(cell, p));
        Assert.False(InSquare(cell, new Vector2(p.X, p.Y), 0));
        Assert.False(TerrainTriangles.Contains(cell, new Vector3(-1e-7f, 36f, 0.5f)));
    }

    [Fact(DisplayName = "issue #29: find_cell(0xA1010033, [(192, 23.999998) r 4]) — 0xA101003A does not contain the centre in retail's float32 either")]
    public void TheServerCaseIsSettled()
    {
        var p = new Vector3(192f, Ulps.Step(24f, -1), 0.5f);
        Assert.Equal(23.999998f, p.Y);
        Assert.False(TerrainTriangles.Contains(new CellId(0xA101003A), p));
        Assert.True(TerrainTriangles.Contains(new CellId(0xA1010039), p));
        var answer = new ReferenceAdapter().FindCell(new CellId(0xA1010033), [new Sphere(p, 4f)], CellId.None);
        Assert.Contains(new CellId(0xA101003A), answer.Cells);
        Assert.Equal(new CellId(0xA1010039), answer.Containing);
    }

    // A coordinate of the cell: its west/south line, its east/north line or a point between, moved by a few tenths of
    // a micrometre and then by whole ulps.
    private static Gen<Func<float, float>> Coordinate { get; } =
        Gen.Zip(Gen.Elements(0f, 0f, 24f, 24f, 12f, 6f, 18f), Gen.Zip(Offsets, Gen.Elements(0f, 0f, 0f, -1e-7f, 1e-7f, -5e-7f, 5e-7f, -2e-6f, 2e-6f)))
            .Select(t => (Func<float, float>)(line => Ulps.Step(line + t.Item1 + t.Item2.Item2, t.Item2.Item1)));

    private static bool InSquare(CellId cell, Vector2 p, float margin)
    {
        int idx = cell.Low - 1;
        double west = 24.0 * (idx >> 3), south = 24.0 * (idx & 7);
        return p.X >= west - margin && p.X <= west + 24 + margin && p.Y >= south - margin && p.Y <= south + 24 + margin;
    }

    private static CellId FirstCell(bool cut, int cx, int cy)
    {
        for (int bx = 0; bx < 255; bx++)
        {
            if (TerrainTriangles.CutsSouthWestToNorthEast((bx * 8) + cx, (10 * 8) + cy) == cut)
            {
                return new CellId((byte)bx, 10, (ushort)((cx * 8) + cy + 1));
            }
        }

        throw new InvalidOperationException("no such cell");
    }
}
