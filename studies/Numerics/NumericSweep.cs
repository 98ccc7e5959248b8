using System.Collections.Concurrent;
using System.Diagnostics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Invariants;
using AcPhys.Studies.Invariants;

namespace AcPhys.Studies.Numerics;

/// <summary>The outcome of a numeric sweep.</summary>
/// <param name="Domain">What was swept.</param>
/// <param name="Points">Points swept.</param>
/// <param name="LandChecks">LandDefs invariant checks (every invariant on every point).</param>
/// <param name="OutdoorQueries">Outdoor queries compared with the exact oracle (points × radii).</param>
/// <param name="Float32Disagreements">Float32-mode disagreements with the exact oracle, by explaining rounding ("unexplained" when none).</param>
/// <param name="DoubleDisagreements">Double-mode disagreements with the exact oracle (must be 0).</param>
/// <param name="Failures">The first few failures: a LandDefs violation, an AdjustToOutside answer not the exact one, an unexplained or double-mode disagreement.</param>
/// <param name="Example">One explained float32 disagreement per rounding, for the docs.</param>
/// <param name="Elapsed">Wall time.</param>
public sealed record NumericSweepResult(
    string Domain,
    long Points,
    long LandChecks,
    long OutdoorQueries,
    IReadOnlyDictionary<string, long> Float32Disagreements,
    long DoubleDisagreements,
    IReadOnlyList<string> Failures,
    IReadOnlyDictionary<string, string> Example,
    TimeSpan Elapsed);

/// <summary>
/// Checks a point set whole (parallel, no sampling): every LandDefs invariant on (cell, x, y); AdjustToOutside's cell
/// and re-based point against the exact rational answer; and the outdoor query at every radius of
/// <see cref="ExtremePoints.Radii"/> in float32 and double mode against <see cref="ExactOutdoor"/>.
/// </summary>
public static class NumericSweep
{
    /// <summary>Sweeps the points.</summary>
    /// <param name="domain">A name for reports.</param>
    /// <param name="points">The points.</param>
    /// <param name="float32">The retail (float32) implementation.</param>
    /// <param name="exactMode">The double-precision implementation, which must agree with the oracle everywhere.</param>
    /// <returns>The result.</returns>
    public static NumericSweepResult Run(string domain, IReadOnlyList<SweepPoint> points, ICellPhysics float32, ICellPhysics exactMode)
    {
        var stopwatch = Stopwatch.StartNew();
        var failures = new ConcurrentQueue<string>();
        var disagreements = new ConcurrentDictionary<string, long>();
        var examples = new ConcurrentDictionary<string, string>();
        long landChecks = 0, queries = 0, doubleBad = 0;
        Parallel.For(0, points.Count, () => (0L, 0L, 0L), (i, _, tally) =>
        {
            var p = points[i];
            var lc = new LandCase(p.Cell, p.X, p.Y, new Lcoord(8 * p.Cell.BlockX, 8 * p.Cell.BlockY));
            foreach (var invariant in LandInvariants.All)
            {
                var outcome = invariant.Check(float32, lc);
                if (outcome.IsViolation)
                {
                    Note(failures, $"{invariant.Id} at {p}: {outcome.Message}");
                }
            }

            if (CheckAdjust(float32, p) is string adjustFailure)
            {
                Note(failures, adjustFailure);
            }

            long q = 0, bad = 0;
            var land = p.Cell.IsLand ? p.Cell : new CellId(p.Cell.BlockX, p.Cell.BlockY, 1);
            foreach (float r in ExtremePoints.Radii)
            {
                var query = new OutdoorCase(land, [new Sphere(new System.Numerics.Vector3(p.X, p.Y, 0.5f), r)]);
                var f = PrecisionCheck.Compare(float32, query);
                var d = PrecisionCheck.Compare(exactMode, query);
                if (f is null || d is null)
                {
                    continue;
                }

                q++;
                if (!f.Agrees)
                {
                    disagreements.AddOrUpdate(f.Reason, 1, (_, n) => n + 1);
                    examples.TryAdd(f.Reason, $"{query}: {f.Detail}");
                    if (!f.Explained)
                    {
                        Note(failures, $"unexplained float32 disagreement at {query}: {f.Detail}");
                    }
                }

                if (!d.Agrees)
                {
                    bad++;
                    Note(failures, $"double mode disagrees with the exact oracle at {query}: {d.Detail}");
                }
            }

            return (tally.Item1 + LandInvariants.All.Count, tally.Item2 + q, tally.Item3 + bad);
        },
        tally =>
        {
            Interlocked.Add(ref landChecks, tally.Item1);
            Interlocked.Add(ref queries, tally.Item2);
            Interlocked.Add(ref doubleBad, tally.Item3);
        });
        stopwatch.Stop();
        return new NumericSweepResult(domain, points.Count, landChecks, queries, disagreements, doubleBad, [.. failures], examples, stopwatch.Elapsed);
    }

    /// <summary>
    /// Checks AdjustToOutside against exact arithmetic: success exactly when the snapped column is on the map, the
    /// column's cell, and a re-based point that is the exact re-base rounded once to float32.
    /// </summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="p">The point.</param>
    /// <returns>A failure message, or null.</returns>
    public static string? CheckAdjust(ICellPhysics impl, SweepPoint p)
    {
        var r = impl.AdjustToOutside(p.Cell, p.X, p.Y);
        var column = ExactOutdoor.Column(p.Cell, p.X, p.Y);
        if (column is not var (gx, gy, _, _))
        {
            return r.Ok ? $"AdjustToOutside at {p} succeeded ({r.Cell}) where the exact column is off the map or invalid" : null;
        }

        var cell = Oracle.CellOf((int)gx, (int)gy);
        float ex = RoundedRebase(p.X), ey = RoundedRebase(p.Y);
        return r.Ok && r.Cell == cell && r.X == ex && r.Y == ey
            ? null
            : $"AdjustToOutside at {p} = {r.Ok} {r.Cell} ({FloatText.Format(r.X)}, {FloatText.Format(r.Y)}), exact {cell} ({FloatText.Format(ex)}, {FloatText.Format(ey)})";
    }

    /// <summary>Returns the exact re-base of a snapped coordinate, v − 192·⌊v/192⌋, rounded once to float32.</summary>
    /// <param name="v">A finite block-frame coordinate.</param>
    /// <returns>The rounded re-base.</returns>
    public static float RoundedRebase(float v)
    {
        var d = Dyadic.Of(Oracle.Snap(v));
        var rebased = d - new Dyadic(d.FloorDiv(192) * Dyadic.Of(192).Units);
        return (float)rebased.ToDouble(); // the exact re-base has ≤ 44 significant bits: exact in double, one rounding here
    }

    private static void Note(ConcurrentQueue<string> failures, string message)
    {
        if (failures.Count < 10)
        {
            failures.Enqueue(message);
        }
    }
}
