using System.Diagnostics;
using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Generators;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Studies.Numerics;

/// <summary>One row of the accuracy table: a case source and a boundary class.</summary>
/// <param name="Source">Where the queries came from.</param>
/// <param name="Class">The boundary class (<see cref="AccuracyClass"/>).</param>
/// <param name="Queries">Queries compared.</param>
/// <param name="Float32Cells">Queries whose float32 cell set differs from the exact one.</param>
/// <param name="Float32Pick">Queries whose float32 containing cell differs.</param>
/// <param name="Float32Any">Queries where either differs.</param>
/// <param name="DoubleAny">Queries where the double mode differs (expected 0).</param>
/// <param name="Reasons">Float32 disagreements by first explaining rounding.</param>
public sealed record AccuracyRow(string Source, string Class, long Queries, long Float32Cells, long Float32Pick, long Float32Any, long DoubleAny, IReadOnlyDictionary<string, long> Reasons);

/// <summary>One example of a float32 disagreement.</summary>
/// <param name="Source">The source.</param>
/// <param name="Class">The boundary class.</param>
/// <param name="Reason">The explaining rounding.</param>
/// <param name="Text">The query and both answers.</param>
public sealed record AccuracyExample(string Source, string Class, string Reason, string Text);

/// <summary>The accuracy measurement.</summary>
/// <param name="Rows">One row per source × class.</param>
/// <param name="Examples">The first example per source × class × reason.</param>
/// <param name="Elapsed">Wall time.</param>
public sealed record AccuracyReport(IReadOnlyList<AccuracyRow> Rows, IReadOnlyList<AccuracyExample> Examples, TimeSpan Elapsed);

/// <summary>
/// Measures how often each fidelity mode (retail float32, double reference) disagrees with the exact rational oracle,
/// over the suite's generated queries, fine-mantissa queries (<see cref="FineFloats"/>) and every step of generated
/// walks, split by boundary class. Indoors, <see cref="IndoorAccuracyRun"/> compares the AABB cells with the BSP.
/// </summary>
public static class AccuracyRun
{
    /// <summary>Gets the source names, in table order.</summary>
    public static IReadOnlyList<string> Sources { get; } = ["suite generators", "fine floats", "walk steps"];

    /// <summary>Runs the measurement.</summary>
    /// <param name="seed">The seed of every source.</param>
    /// <param name="cases">Queries per source (walks: walks, each giving several steps).</param>
    /// <returns>The report.</returns>
    public static AccuracyReport Run(int seed, int cases)
    {
        var stopwatch = Stopwatch.StartNew();
        var rnd = new Rnd((ulong)seed, 0x9E3779B97F4A7C15UL);
        var queries = new List<(string Source, OutdoorCase Query)>();
        queries.AddRange(Gen.Sample(OutdoorGens.Cases, cases, rnd, 50).Select(q => (Sources[0], q)));
        queries.AddRange(FineFloats.Cases(seed, cases).Select(q => (Sources[1], q)));
        foreach (var walk in Gen.Sample(WalkGens.Walks, cases / 4, rnd, 50))
        {
            queries.AddRange(WalkRunner.Run(ReferenceAdapter.Instance, walk).Select(step => (Sources[2], step.Query)));
        }

        var results = new (string Class, PrecisionComparison? F, PrecisionComparison? D)[queries.Count];
        Parallel.For(0, queries.Count, i =>
        {
            var q = queries[i].Query;
            results[i] = (AccuracyClass.Of(q), PrecisionCheck.Compare(ReferenceAdapter.Instance, q), PrecisionCheck.Compare(ReferenceAdapter.Double, q));
        });

        var rows = new List<AccuracyRow>();
        var examples = new List<AccuracyExample>();
        foreach (string source in Sources)
        {
            foreach (string cls in AccuracyClass.All)
            {
                long n = 0, cells = 0, pick = 0, any = 0, dbl = 0;
                var reasons = new SortedDictionary<string, long>(StringComparer.Ordinal);
                for (int i = 0; i < results.Length; i++)
                {
                    var (c, f, d) = results[i];
                    if (queries[i].Source != source || c != cls || f is null || d is null)
                    {
                        continue;
                    }

                    n++;
                    cells += f.CellsDiffer ? 1 : 0;
                    pick += f.PickDiffers ? 1 : 0;
                    dbl += d.Agrees ? 0 : 1;
                    if (!f.Agrees)
                    {
                        any++;
                        reasons[f.Reason] = reasons.GetValueOrDefault(f.Reason) + 1;
                        if (!examples.Any(e => e.Source == source && e.Class == cls && e.Reason == f.Reason))
                        {
                            examples.Add(new AccuracyExample(source, cls, f.Reason, $"{queries[i].Query} → {f.Detail}"));
                        }
                    }
                }

                rows.Add(new AccuracyRow(source, cls, n, cells, pick, any, dbl, reasons));
            }
        }

        stopwatch.Stop();
        return new AccuracyReport(rows, examples, stopwatch.Elapsed);
    }
}
