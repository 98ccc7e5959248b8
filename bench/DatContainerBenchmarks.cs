using AcPhys.Core;
using AcPhys.Formats.Dat;
using AcPhys.Formats.Dat.Container;
using AcPhys.Spec.Scenes;
using BenchmarkDotNet.Attributes;
using BenchmarkDotNet.Engines;

namespace AcPhys.Bench;

/// <summary>
/// The dat container reader on the largest world the writer builds here (docs/dat-container.md "Speed"): a cottage of
/// three rooms and a storey in each of <see cref="Side"/>² landblocks, block size 1,024 — over 100 MB, written once into
/// the temp folder (never committed) and reused. Open + read the directory; 1,000 env cells fetched on demand; one
/// landblock's scene extracted.
/// </summary>
[MemoryDiagnoser]
[SimpleJob(RunStrategy.Monitoring, launchCount: 1, warmupCount: 1, iterationCount: 5)]
public class DatContainerBenchmarks
{
    /// <summary>Blocks per side of the world.</summary>
    public const int Side = 136;

    private static readonly string Cell = Path.Combine(Path.GetTempPath(), $"acphys-bench-cell-{Side}.dat");
    private static readonly string Portal = Path.Combine(Path.GetTempPath(), $"acphys-bench-portal-{Side}.dat");
    private DatWorld? world;
    private uint[] cells = [];
    private LandblockId[] blocks = [];
    private int next;

    /// <summary>Writes the world when absent, opens it, picks the objects to fetch.</summary>
    [GlobalSetup]
    public void Setup()
    {
        if (!File.Exists(Cell) || !File.Exists(Portal))
        {
            Build();
        }

        world = DatWorld.Open(Cell, Portal);
        var random = new Random(43);
        var ids = world.Cell.Ids.Where(id => (id & 0xFFFF) is >= 0x0100 and < 0xFFFE).ToArray();
        cells = [.. Enumerable.Range(0, 1000).Select(_ => ids[random.Next(ids.Length)])];
        blocks = [.. world.Landblocks().OrderBy(_ => random.Next()).Take(64)];
        Console.WriteLine($"// world: {world.Cell}; {world.Portal}");
    }

    /// <summary>Closes the world.</summary>
    [GlobalCleanup]
    public void Cleanup() => world?.Dispose();

    /// <summary>Opens the cell database: header and the whole directory.</summary>
    /// <returns>The number of objects.</returns>
    [Benchmark(Description = "open + read directory (cell dat)")]
    public int OpenAndReadDirectory()
    {
        using var c = DatContainer.Open(Cell);
        return c.Count;
    }

    /// <summary>Fetches 1,000 env cells on demand.</summary>
    /// <returns>Bytes read.</returns>
    [Benchmark(Description = "1,000 env cells on demand", OperationsPerInvoke = 1000)]
    public long ReadObjects()
    {
        long n = 0;
        foreach (uint id in cells)
        {
            n += world!.Cell.Read(id).Length;
        }

        return n;
    }

    /// <summary>Extracts one landblock's scene (whole block).</summary>
    /// <returns>Cells kept.</returns>
    [Benchmark(Description = "scene extraction per landblock")]
    public int Extract() => SceneExtraction.Extract(world!, new ScenePlace(blocks[next++ % blocks.Length])).Report.KeptCells;

    private static void Build()
    {
        // One cottage (three rooms, a storey, a back door) in the middle of block 0x4041 with no neighbours declared,
        // moved by whole blocks: identical geometry everywhere, so the first scene's Environment serves them all.
        var cottage = SceneKit.Cottage(new CottagePlan((192.0 * 0x40) + 80, (192.0 * 0x41) + 80, 0.3f, 3, 6, 5, 0x5A, BackDoor: true, Storey: true, LoadNeighbours: false));
        var home = cottage with { UnloadedBlocks = [] };
        var environment = DatSceneWriter.Write(home, "bench", "bench").Records.Where(r => r.Record.PortalDat).Select(r => (r.Record.Id, r.Bytes)).ToList();
        IEnumerable<(uint, byte[])> CellRecords()
        {
            for (int x = 0; x < Side; x++)
            {
                for (int y = 0; y < Side; y++)
                {
                    var scene = home.Translated(x - 0x40, y - 0x41);
                    foreach (var (record, bytes) in DatSceneWriter.Write(scene, "bench", "bench").Records.Where(r => !r.Record.PortalDat))
                    {
                        yield return (record.Id, bytes);
                    }
                }
            }
        }

        DatContainerWriter.Write(Cell, CellRecords(), DatSet.Cell, 1024);
        DatContainerWriter.Write(Portal, environment, DatSet.Portal, 1024);
    }
}
