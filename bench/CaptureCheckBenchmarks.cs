using System.Globalization;
using System.Numerics;
using AcPhys.Core;
using AcPhys.Formats.Capture;
using AcPhys.Spec.Capture;
using BenchmarkDotNet.Attributes;

namespace AcPhys.Bench;

/// <summary>
/// <c>acphys capture check</c> in process (issue 50: ≥ 200,000 outdoor frames/s per core): 1,000,000 frames of
/// capture text (<see cref="CaptureFrames"/>) read by the real reader and judged by the real checker, per frame; beside
/// it the reference's own cost per frame, core's outdoor find_cell_list on the same frames (parsed beforehand).
/// </summary>
[MemoryDiagnoser]
public class CaptureCheckBenchmarks
{
    private const int Frames = 1_000_000;

    private readonly CellArray array = new();
    private byte[] text = [];
    private (CellId Cell, Vector3 P)[] parsed = [];

    [GlobalSetup]
    public void Setup()
    {
        text = CaptureFrames.Bytes(Frames);
        parsed = new (CellId, Vector3)[Frames];
        int i = 0;
        foreach (var line in System.Text.Encoding.UTF8.GetString(text).Split('\n'))
        {
            if (line.Length == 0 || line[0] == '#')
            {
                continue;
            }

            var f = line.Split('\t');
            parsed[i++] = (new CellId(uint.Parse(f[1].AsSpan(2), NumberStyles.HexNumber, CultureInfo.InvariantCulture)), new Vector3(float.Parse(f[2], CultureInfo.InvariantCulture), float.Parse(f[3], CultureInfo.InvariantCulture), 0));
        }
    }

    [Benchmark(Description = "capture check, per frame (reader + checker, candidates judged)", OperationsPerInvoke = Frames)]
    public long CheckCapture()
    {
        using var reader = CaptureReaders.Open(new MemoryStream(text, writable: false), "bench", CaptureFormat.Native, new CaptureOptions(null, null));
        var report = new CaptureChecker(CaptureChecker.OutdoorOnly(PickPolicy.Retail, default)).Check(reader);
        return report.Divergent != 0 ? throw new InvalidOperationException($"{report.Divergent} divergent frames in the reference's own capture") : report.Judged;
    }

    [Benchmark(Description = "reference find_cell_list outdoor, per frame (same frames)", OperationsPerInvoke = Frames)]
    public uint ReferenceFindCell()
    {
        uint sum = 0;
        Span<Sphere> body = stackalloc Sphere[1];
        var before = CellId.None;
        for (int i = 0; i < parsed.Length; i++)
        {
            var (cell, p) = parsed[i];
            var from = before.IsNone ? cell : before;
            var q = p - LandDefs.GetBlockOffset(cell, from);
            body[0] = new Sphere(q, 0.48f);
            sum += CellQuery.FindCellListOutdoor(array, from, q, body, before, PickPolicy.Retail, OpenLand.Instance).Value;
            before = cell;
        }

        return sum;
    }
}
