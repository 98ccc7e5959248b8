using System.Diagnostics;

namespace AcPhys.Cli.Bench;

/// <summary>One measured row: median ns per operation over the rounds, and bytes allocated per operation.</summary>
/// <param name="Op">The operation.</param>
/// <param name="NsPerOp">Median ns/op.</param>
/// <param name="MinNsPerOp">Fastest round's ns/op.</param>
/// <param name="BytesPerOp">Bytes allocated on the thread per op over all measured rounds.</param>
/// <param name="Iterations">Measured iterations in total.</param>
internal sealed record BenchRow(BenchOp Op, double NsPerOp, double MinNsPerOp, double BytesPerOp, long Iterations);

/// <summary>
/// A short in-process benchmark (Stopwatch, warm-up until the JIT's optimised tier runs, then timed rounds,
/// <see cref="GC.GetAllocatedBytesForCurrentThread"/> for bytes/op). BenchmarkDotNet (bench/) is the precise one.
/// </summary>
internal static class MicroBench
{
    /// <summary>Measures one operation.</summary>
    /// <param name="op">The operation.</param>
    /// <param name="roundMs">Target length of one round, milliseconds.</param>
    /// <param name="rounds">Timed rounds.</param>
    /// <returns>The row.</returns>
    public static BenchRow Measure(BenchOp op, int roundMs, int rounds)
    {
        // Warm-up: long enough for tiered compilation to promote the loop (≥ 30 calls and a background recompile).
        int n = 1_000;
        var warm = Stopwatch.StartNew();
        while (warm.ElapsedMilliseconds < Math.Max(150, roundMs))
        {
            op.Loop(n);
        }

        // Calibrate a batch size of about one round.
        var probe = Stopwatch.StartNew();
        op.Loop(n);
        double perOp = Math.Max(probe.Elapsed.TotalNanoseconds / n, 0.1);
        int batch = (int)Math.Clamp(roundMs * 1e6 / perOp, 1_000, 200_000_000);

        // Only timestamps (no Stopwatch objects) between the two allocation readings: any byte counted is the op's.
        var times = new double[rounds];
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int r = 0; r < rounds; r++)
        {
            long start = Stopwatch.GetTimestamp();
            op.Loop(batch);
            times[r] = Stopwatch.GetElapsedTime(start).TotalNanoseconds / batch;
        }

        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
        Array.Sort(times);
        return new BenchRow(op, times[rounds / 2], times[0], (double)allocated / ((long)batch * rounds), (long)batch * rounds);
    }
}
