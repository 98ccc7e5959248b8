using System.Numerics;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Capture;

namespace AcPhys.Props.Capture;

/// <summary>
/// CAPTURE-PRECISION-REGIONS: near a boundary the precision interval is sampled at a point of every region its
/// boundaries cut it into, so an answer held only between two boundaries (two spheres' edges, or r and 24 − r when
/// r is near 12 m) is seen too, not only the answers at the two ends.
/// </summary>
public sealed class CaptureSamplesTests
{
    [Theory(DisplayName = "CAPTURE-PRECISION-REGIONS: each region between the boundaries inside ± h holds one sample, and the two ends are samples")]
    [InlineData(24.0, 0.0005, 0.48f, 0.0f, 0.0f)] // one cell line inside: the two ends
    [InlineData(36.0, 0.0005, 12.0001f, 0.0f, 0.0f)] // r and 24 − r both within 0.1 mm of the centre
    [InlineData(48.2, 0.0005, 0.2f, 0.48f, 0.2798f)] // sphere 0's r-line at 48.2 and sphere 1's cell-edge line 0.0002 apart
    public void EveryRegionIsSampled(double v, double h, float r0, float r1, float offset1)
    {
        BodySphere[] body = r1 > 0 ? [new(Vector3.Zero, r0), new(new Vector3(offset1, 0, 0), r1)] : [new(Vector3.Zero, r0)];
        var samples = new double[1];
        int n = OutdoorJudge.Samples(ref samples, v, h, body, judgeCells: true, static o => o.X);

        var cuts = Boundaries(v, h, body);
        Assert.Equal(cuts.Count + 1, n);
        Assert.Equal(-h, samples[0]);
        Assert.Equal(h, samples[n - 1]);
        var edges = cuts.Prepend(-h).Append(h).ToArray();
        for (int k = 0; k + 1 < edges.Length; k++)
        {
            int inRegion = samples.Take(n).Count(s => s >= edges[k] && s <= edges[k + 1] && (k == 0 || s > edges[k]) && (k + 2 == edges.Length || s < edges[k + 1]));
            Assert.True(inRegion == 1, $"region {k} ({edges[k]}, {edges[k + 1]}) holds {inRegion} samples of [{string.Join(", ", samples.Take(n))}]");
        }
    }

    // The boundaries, written out independently: for each sphere's centre u = v + offset, the 24 m lines and r into the
    // cell from each of its two edges, those strictly inside (−h, h) of the offset, sorted.
    private static List<double> Boundaries(double v, double h, BodySphere[] body)
    {
        var cuts = new List<double>();
        foreach (var s in body)
        {
            double u = v + s.Offset.X, west = 24 * Math.Floor(u / 24);
            foreach (double b in new[] { west, west + 24, west + s.Radius, west - s.Radius, west + 24 + s.Radius, west + 24 - s.Radius })
            {
                if (b - u > -h && b - u < h)
                {
                    cuts.Add(b - u);
                }
            }
        }

        cuts.Sort();
        return cuts;
    }
}
