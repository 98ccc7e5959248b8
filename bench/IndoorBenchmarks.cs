using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;
using BenchmarkDotNet.Attributes;

namespace AcPhys.Bench;

/// <summary>
/// find_cell_list indoors (facts §4–§5), retail BSP cells against the ACME AABB cells, on the fixed cases of
/// <see cref="IndoorBenchCases"/> (a box-room cottage and one with an L-shaped and a stairs room; inside a room,
/// straddling a door portal, outdoors next to the building): ns/op and bytes allocated (must be 0).
/// </summary>
[MemoryDiagnoser]
public class IndoorBenchmarks
{
    private readonly CellArray array = new();
    private CellScene scene = CellScene.Open;
    private IndoorBenchCase query = IndoorBenchCases.All[0];

    /// <summary>Gets or sets the cell volumes: retail BSP semantics or the AABB.</summary>
    [Params(VolumeMode.Bsp, VolumeMode.Aabb)]
    public VolumeMode Volumes { get; set; }

    /// <summary>Gets or sets the case's short key (<see cref="IndoorBenchCase.ShortKey"/>; bench/results/*/README.md lists them).</summary>
    [ParamsSource(nameof(CaseNames))]
    public string Case { get; set; } = string.Empty;

    /// <summary>Gets the case names.</summary>
    public static IEnumerable<string> CaseNames => IndoorBenchCases.All.Select(c => c.ShortKey);

    /// <summary>Builds the scene (outside the timing).</summary>
    [GlobalSetup]
    public void Setup()
    {
        query = IndoorBenchCases.All.First(c => c.ShortKey == Case);
        scene = SceneBuild.Build(query.Description, Volumes);
        FindCellList(); // grow the array once
    }

    [Benchmark(Description = "find_cell_list indoor")]
    public CellId FindCellList() =>
        SceneQuery.FindCellList(array, scene, query.Position, query.Spheres, query.Position, query.Options).Containing;
}
