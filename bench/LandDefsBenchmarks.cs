using AcPhys.Core;
using BenchmarkDotNet.Attributes;

namespace AcPhys.Bench;

/// <summary>The LandDefs hot paths (facts §2), float32 and the double reference: ns/op and bytes allocated (must be 0).</summary>
[MemoryDiagnoser]
public class LandDefsBenchmarks
{
    private readonly CellId cell = new(0xA9B40031);

    [Benchmark(Description = "AdjustToOutside across a block line")]
    public CellId AdjustToOutside()
    {
        var id = cell;
        float x = 150f, y = -0.5f;
        LandDefs.AdjustToOutside(ref id, ref x, ref y);
        return id;
    }

    [Benchmark(Description = "AdjustToOutside across a block line, double reference")]
    public CellId AdjustToOutsideDouble()
    {
        var id = cell;
        double x = 150, y = -0.5;
        LandDefs.AdjustToOutsideInDouble(ref id, ref x, ref y);
        return id;
    }

    [Benchmark(Description = "GetOutsideLcoord, double reference")]
    public Lcoord GetOutsideLcoordDouble()
    {
        LandDefs.GetOutsideLcoordInDouble(cell, 150.0, -0.5, out var lc);
        return lc;
    }

    [Benchmark(Description = "GetOutsideLcoord")]
    public Lcoord GetOutsideLcoord()
    {
        LandDefs.GetOutsideLcoord(cell, 150f, -0.5f, out var lc);
        return lc;
    }

    [Benchmark(Description = "GidToLcoord + LcoordToGid")]
    public CellId RoundTrip()
    {
        LandDefs.GidToLcoord(cell, out var lc);
        return LandDefs.LcoordToGid(lc);
    }
}
