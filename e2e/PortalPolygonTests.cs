using System.Numerics;
using AcPhys.Formats;
using AcPhys.Formats.Dat;
using AcPhys.Formats.Scenes;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.E2E;

/// <summary>
/// Issue #29, portal polygons in scene JSON: a scene may carry each portal's polygon (optional for ports that take
/// planes); the plane derived from the polygon — the normalised sum of fan cross products, as a dat reader derives it
/// (docs/dat-scenes.md) — is the plane given, and a polygon that says otherwise is refused.
/// </summary>
public sealed class PortalPolygonTests
{
    private const ulong Seed = 29_003;

    [Fact]
    public void ThePlaneDerivedFromEachPortalPolygonIsThePlaneGiven()
    {
        var scenes = Gen.Sample(SceneGens.Recipes.Select(r => r.Build().Scene), 60, new Rnd(Seed, 0x9E3779B97F4A7C15UL), 50);
        int portals = 0;
        foreach (var scene in scenes)
        {
            string json = SceneJson.Write(PortalPolygons.With(scene));
            var read = SceneJson.Read(json, "polygons");
            foreach (var (cell, original) in read.Cells.Zip(scene.Cells))
            {
                foreach (var (portal, given) in cell.Portals.Zip(original.Portals))
                {
                    portals++;
                    var polygon = Assert.IsAssignableFrom<IReadOnlyList<Vector3>>(portal.Polygon);
                    var derived = PolygonPlane.Of(polygon);
                    var unit = PolygonPlane.Unit(given.Plane);
                    Assert.True(derived is { } d && Vector3.Dot(d.Normal, unit.Normal) > 1 - 1e-6f && MathF.Abs(d.D - unit.D) < 1e-4f, $"seed {Seed}: {cell.Id} portal plane {unit} but polygon plane {derived}");
                    Assert.Equal(given.Plane, portal.Plane); // the plane travels as it was given
                }
            }
        }

        Assert.True(portals > 100, $"only {portals} portals sampled");
    }

    [Fact]
    public void APolygonWoundAgainstItsPlaneIsRefused()
    {
        var scene = Gen.Sample(SceneGens.Recipes.Select(r => r.Build().Scene), 20, new Rnd(Seed, 0x9E3779B97F4A7C15UL), 50).First(s => s.Cells.Any(c => c.Portals.Count > 0));
        var withPolygons = PortalPolygons.With(scene);
        var cell = withPolygons.Cells.First(c => c.Portals.Count > 0);
        var reversed = cell with { Portals = [cell.Portals[0] with { Polygon = [.. cell.Portals[0].Polygon!.Reverse()] }, .. cell.Portals.Skip(1)] };
        var bad = withPolygons with { Cells = [.. withPolygons.Cells.Select(c => c.Id == cell.Id ? reversed : c)] };
        var e = Assert.Throws<InputFormatException>(() => SceneJson.Read(SceneJson.Write(bad), "reversed"));
        Assert.Contains("is not the portal's plane", e.Message, StringComparison.Ordinal);
        Assert.Null(SceneJson.Read(SceneJson.Write(scene), "planes only").Cells.First(c => c.Portals.Count > 0).Portals[0].Polygon); // optional
    }
}
