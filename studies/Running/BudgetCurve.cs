using System.Diagnostics;
using AcPhys.Contract;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Studies.Running;

/// <summary>When one seed first caught one planted fault.</summary>
/// <param name="Fault">The fault id.</param>
/// <param name="Seed">The base seed (as a profile's).</param>
/// <param name="CasesToDetect">Generated cases per invariant at which a catching invariant first failed, or null when none did within the cap.</param>
/// <param name="Invariant">The invariant that caught it first.</param>
/// <param name="Elapsed">Time spent running the catchers for this seed.</param>
public sealed record DetectionSample(string Fault, ulong Seed, long? CasesToDetect, string? Invariant, TimeSpan Elapsed);

/// <summary>
/// The verification budget curve: for a planted fault and a base seed, how many generated cases per invariant the
/// fault's catching invariants (<see cref="PlantedFault.CaughtBy"/>) need before one fails. One run per seed gives
/// the whole curve, since an invariant's run at budget N checks the first N cases of the same seeded sequence
/// (CatalogueRunner counts cases up to the first failure). Detection by other invariants could only come earlier,
/// so the curves are lower bounds on what the full catalogue does.
/// </summary>
public static class BudgetCurve
{
    /// <summary>Measures one fault with one base seed.</summary>
    /// <param name="fault">The fault.</param>
    /// <param name="baseSeed">The base seed; each invariant's seed is derived from it as the profiles do.</param>
    /// <param name="maxCases">The cap: cases per invariant.</param>
    /// <param name="catchers">The invariants that count as catching it; default the fault's own <see cref="PlantedFault.CaughtBy"/> (a known-bug entry passes its <see cref="KnownBug.CaughtBy"/>).</param>
    /// <returns>The sample.</returns>
    public static DetectionSample Measure(PlantedFault fault, ulong baseSeed, int maxCases, IReadOnlyList<string>? catchers = null)
    {
        var stopwatch = Stopwatch.StartNew();
        var impl = PlantedFaults.Create(fault.Id);
        long? best = null;
        string? by = null;
        foreach (string id in catchers ?? fault.CaughtBy)
        {
            var invariant = InvariantCatalogue.Find(id);
            if (invariant is null || !invariant.IsTestable(impl))
            {
                continue;
            }

            int cap = (int)(best ?? maxCases);
            var result = invariant.Run(impl, cap, Seed.Derive(baseSeed, invariant.Id), maxClasses: 1);
            if (result.Status == ResultStatus.Failed && (best is null || result.Cases < best))
            {
                best = result.Cases;
                by = invariant.Id;
            }
        }

        stopwatch.Stop();
        return new DetectionSample(fault.Id, baseSeed, best, by, stopwatch.Elapsed);
    }

    /// <summary>Tests whether the exhaustive sweeps of the pr and nightly profiles catch the fault, whatever the budget.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The invariant whose sweep caught it, or null.</returns>
    public static string? CaughtBySweeps(PlantedFault fault)
    {
        var impl = PlantedFaults.Create(fault.Id);
        foreach (var invariant in InvariantCatalogue.Land)
        {
            if (invariant.IsTestable(impl) && Exhaustive.For(invariant, impl) is { FirstViolation: not null })
            {
                return invariant.Id;
            }
        }

        return null;
    }

    /// <summary>Times the whole catalogue (generated cases only, no sweeps) against the reference at a budget: the seconds axis.</summary>
    /// <param name="cases">Cases per invariant.</param>
    /// <param name="baseSeed">The base seed.</param>
    /// <returns>The wall time.</returns>
    public static TimeSpan CatalogueTime(int cases, ulong baseSeed)
    {
        var stopwatch = Stopwatch.StartNew();
        CatalogueRunner.RunCatalogue(ReferenceAdapter.Instance, new Profile("budget", cases, baseSeed, false));
        return stopwatch.Elapsed;
    }

    /// <summary>Returns the i-th of a reproducible series of independent base seeds (splitmix64 of a master seed).</summary>
    /// <param name="master">The master seed.</param>
    /// <param name="index">The index.</param>
    /// <returns>The seed.</returns>
    public static ulong SeedAt(ulong master, int index)
    {
        ulong z = master + (0x9E3779B97F4A7C15UL * (ulong)(index + 1));
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9UL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBUL;
        return z ^ (z >> 31);
    }

    /// <summary>Returns the detection probability at a budget: the share of samples caught within it.</summary>
    /// <param name="samples">Samples of one fault.</param>
    /// <param name="cases">The budget.</param>
    /// <returns>The probability.</returns>
    public static double Probability(IReadOnlyCollection<DetectionSample> samples, long cases) =>
        samples.Count == 0 ? 0 : (double)samples.Count(s => s.CasesToDetect <= cases) / samples.Count;
}
