using System.Text.RegularExpressions;
using AcPhys.Formats.Dat;
using AcPhys.Formats.Scenes;
using Xunit.Abstractions;

namespace AcPhys.Props.Dat;

/// <summary>Scenes written as retail records (docs/dat-scenes.md) read back unchanged, or as the documented normal form.</summary>
public sealed class DatRoundTripProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "Every corpus scene walk exports to records and imports back with no change (exact floats).")]
    public void CorpusScenesRoundTripExactly()
    {
        Assert.NotEmpty(DatTestSupport.CorpusSceneWalks);
        foreach (var (name, entry) in DatTestSupport.CorpusSceneWalks)
        {
            var scene = entry.SceneWalk!.Scene;
            var (_, back) = DatTestSupport.RoundTrip(scene);
            Assert.True(DatNormalForm.Differences(scene, back, 0).Count == 0, $"{name}: {string.Join("; ", DatNormalForm.Differences(scene, back, 0))}");
            Assert.Equal(Unsigned(SceneJson.Write(scene)), Unsigned(SceneJson.Write(back))); // the text too, but for the sign of zeros
        }

        output.WriteLine($"{DatTestSupport.CorpusSceneWalks.Count} corpus scene walks round-tripped exactly");
    }

    [Fact(DisplayName = "1,000 generated scenes export and import with no change (exact floats, axis-aligned portals bit-exact).")]
    public void GeneratedScenesRoundTripExactly()
    {
        int cells = 0, portals = 0;
        foreach (var scene in DatTestSupport.Generated(1000, 0xDA7A))
        {
            var (_, back) = DatTestSupport.RoundTrip(scene);
            var diff = DatNormalForm.Differences(DatNormalForm.Of(scene), back, 0);
            Assert.True(diff.Count == 0, $"{scene}: {string.Join("; ", diff)}");
            cells += scene.Cells.Count;
            portals += scene.PortalCount;
        }

        output.WriteLine($"1000 scenes, {cells} cells, {portals} portals: no change");
    }

    [Fact(DisplayName = "1,000 multi-piece scenes (L shapes, stairs, rotated plane boxes, oblique portals) come back as their normal form.")]
    public void MultiPieceScenesRoundTripToNormalForm()
    {
        int oblique = 0, exact = 0;
        foreach (var scene in DatTestSupport.MultiPiece(1000, 0xDA7B))
        {
            var (_, back) = DatTestSupport.RoundTrip(scene);
            var normal = DatNormalForm.Of(scene);
            var diff = DatNormalForm.Differences(normal, back, 1e-5f);
            Assert.True(diff.Count == 0, $"{scene}: {string.Join("; ", diff)}");
            foreach (var (a, b) in normal.Cells.SelectMany(c => c.Portals).Zip(back.Cells.SelectMany(c => c.Portals)))
            {
                oblique += PolygonPlane.AxisOf(a.Plane.Normal) is null ? 1 : 0;
                exact += a.Plane == b.Plane ? 1 : 0;
            }

            // The normal form is a fixed point: writing what was read gives it back again.
            var (_, again) = DatTestSupport.RoundTrip(back);
            Assert.Empty(DatNormalForm.Differences(back, again, 1e-5f));
        }

        output.WriteLine($"1000 scenes: {oblique} oblique portal planes (within 1e-5), {exact} portal planes bit-exact");
    }

    private static string Unsigned(string json) => Regex.Replace(json, @"-0(?![\d.eE])", "0");
}
