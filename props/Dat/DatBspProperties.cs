using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Dat;
using Xunit.Abstractions;

namespace AcPhys.Props.Dat;

/// <summary>The trees and polygons in the written records mean what the scene means: BSP answers and portal planes.</summary>
public sealed class DatBspProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "On 5,000 scenes with multi-piece cells, the parsed cell BSP answers point-in-cell and sphere-intersects-cell exactly like core's CellBsp.")]
    public void ParsedBspAnswersLikeCore()
    {
        var random = new Random(0xB5B);
        int cells = 0, multi = 0, points = 0, inside = 0, spheres = 0, outside = 0, onPlane = 0;
        var scenes = DatTestSupport.Generated(2500, 0xB5B0).Concat(DatTestSupport.MultiPiece(2500, 0xB5B1));
        foreach (var scene in scenes)
        {
            var export = DatSceneWriter.Write(scene, "test", "memory");
            var structs = DatTestSupport.Structs(export);
            var records = DatTestSupport.Cells(export);
            foreach (var cell in scene.Cells)
            {
                cells++;
                multi += cell.Pieces.Count > 1 ? 1 : 0;
                var tree = structs[records[cell.Id.Value].CellStructure].CellBsp;
                var core = SceneBuild.Cell(cell, VolumeMode.Bsp).Volume;
                var pieces = cell.Pieces.Select(p => p.ToConvex()).ToArray();
                var lo = core.Bounds.Min - new Vector3(0.5f);
                var hi = core.Bounds.Max + new Vector3(0.5f);
                for (int i = 0; i < 40; i++)
                {
                    var p = lo + ((hi - lo) * new Vector3(random.NextSingle(), random.NextSingle(), random.NextSingle()));
                    if (i % 4 == 0)
                    {
                        // Onto a plane of some piece, where the EPS band decides.
                        var plane = pieces[random.Next(pieces.Length)].Planes[random.Next(4)];
                        p -= plane.Distance(p) * plane.Normal;
                        onPlane++;
                    }

                    bool a = RecordBspEvaluator.PointInside(tree, p);
                    Assert.True(a == core.PointInside(p), $"{cell.Id}: point {p}: records {a}, core {!a}");
                    points++;
                    inside += a ? 1 : 0;
                    float r = random.NextSingle() * 1.5f;
                    var s = RecordBspEvaluator.Sphere(tree, p, r);
                    Assert.Equal(core.SphereIntersects(new Sphere(p, r)), s);
                    spheres++;
                    outside += s == BoundingType.Outside ? 1 : 0;
                }
            }
        }

        output.WriteLine($"{cells} cells ({multi} multi-piece): {points} points ({inside} inside, {onPlane} projected onto a plane), {spheres} spheres ({outside} outside): all equal");
        Assert.True(multi > 1000 && inside > 0 && inside < points && outside > 0 && outside < spheres);
    }

    [Fact(DisplayName = "Each portal polygon's plane, computed from its vertices, is the scene portal's unit plane within float32 tolerance (bit-exact when axis-aligned).")]
    public void PortalPolygonPlanesAreScenePlanes()
    {
        int portals = 0, exact = 0, oblique = 0;
        float worst = 0;
        foreach (var scene in DatTestSupport.Generated(500, 0xC0C0).Concat(DatTestSupport.MultiPiece(500, 0xC0C1)))
        {
            var export = DatSceneWriter.Write(scene, "test", "memory");
            var structs = DatTestSupport.Structs(export);
            var records = DatTestSupport.Cells(export);
            foreach (var cell in scene.Cells)
            {
                var record = records[cell.Id.Value];
                var cs = structs[record.CellStructure];
                for (int i = 0; i < cell.Portals.Count; i++)
                {
                    var polygon = cs.Polygons.Single(p => p.Id == record.Portals[i].PolygonId);
                    var vertices = polygon.VertexIds.Select(v => cs.Vertices.Single(x => x.Id == v).Origin).ToList();
                    var fromVertices = PolygonPlane.Of(vertices)!.Value;
                    var expected = PolygonPlane.Unit(cell.Portals[i].Plane);
                    Assert.Contains(record.Portals[i].PolygonId, cs.PortalPolygonIds);
                    Assert.True(DatNormalForm.Near(expected, fromVertices, 1e-5f), $"{cell.Id} portal {i}: {expected} vs {fromVertices}");
                    bool axis = PolygonPlane.AxisOf(expected.Normal) is not null;
                    Assert.True(!axis || expected == fromVertices, $"{cell.Id} portal {i}: axis plane not bit-exact: {expected} vs {fromVertices}");
                    worst = MathF.Max(worst, Vector3.Distance(expected.Normal, fromVertices.Normal));
                    portals++;
                    exact += expected == fromVertices ? 1 : 0;
                    oblique += axis ? 0 : 1;
                }
            }
        }

        output.WriteLine($"{portals} portal polygons: {exact} bit-exact, {oblique} oblique; worst normal error {worst:E2}");
    }
}
