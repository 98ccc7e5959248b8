using System.Numerics;
using AcPhys.Core;
using BenchmarkDotNet.Attributes;

namespace AcPhys.Bench;

/// <summary>Outdoor-set queries (facts §3–§4): add_all_outside_cells and the outdoor find_cell_list, retail float32 and the double reference; targets ≤ 50 ns and 0 B per query.</summary>
[MemoryDiagnoser]
public class OutdoorBenchmarks
{
    /// <summary>Gets or sets the arithmetic: retail float32 or the exact double reference.</summary>
    [Params(OutdoorPrecision.Float32, OutdoorPrecision.Double)]
    public OutdoorPrecision Precision { get; set; }

    private readonly CellArray array = new();
    private readonly CellId position = new(0xA9B40005);
    private readonly Sphere[] interior = [new Sphere(new Vector3(12, 100, 0.5f), 0.5f)];
    private readonly Sphere[] corner = [new Sphere(new Vector3(0.1f, 0.2f, 0.5f), 0.5f)];
    private readonly Sphere[] body = [new Sphere(new Vector3(0.1f, 0.2f, 0.5f), 0.5f), new Sphere(new Vector3(0.1f, 0.2f, 1.5f), 0.5f), new Sphere(new Vector3(191.9f, 23.9f, 0.5f), 0.6f)];

    [Benchmark(Description = "outside cells, 1 sphere, cell interior (1 cell)")]
    public int Interior() => Query(interior);

    [Benchmark(Description = "outside cells, 1 sphere, 4-block corner (4 cells)")]
    public int Corner() => Query(corner);

    [Benchmark(Description = "outside cells, 3 spheres across lines")]
    public int Body() => Query(body);

    [Benchmark(Description = "find_cell_list outdoor, corner, retail pick")]
    public CellId FindCellCorner() => CellQuery.FindCellListOutdoor(array, position, corner, CellId.None, PickPolicy.Retail, OpenLand.Instance, Fidelity);

    [Benchmark(Description = "find_cell_list outdoor, corner, current-first pick")]
    public CellId FindCellCornerCurrentFirst() => CellQuery.FindCellListOutdoor(array, position, corner, new CellId(0xA9B40001), PickPolicy.CurrentFirst, OpenLand.Instance, Fidelity);

    private OutdoorFidelity Fidelity => new(Precision: Precision);

    private int Query(Sphere[] spheres)
    {
        array.Reset();
        OutdoorCells.AddAllOutsideCells(array, position, Vector3.Zero, spheres, OpenLand.Instance, Fidelity);
        return array.Count;
    }
}
