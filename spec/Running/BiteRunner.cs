using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Running;

/// <summary>
/// Proves the suite bites (docs/bite.md): switches on each catalogue bug's planted fault in the reference and runs
/// the invariants against it, under N seeds, recording which invariants catch it and how soon. Generated cases only
/// (the pr profile's exhaustive sweeps are not used), so a bug must be caught by the properties themselves.
/// </summary>
public static class BiteRunner
{
    /// <summary>Runs catalogue bugs against invariants.</summary>
    /// <param name="bugs">The bugs (pending ones are reported, not run).</param>
    /// <param name="profile">Cases per invariant, and the base seed unless <paramref name="baseSeed"/> is given.</param>
    /// <param name="seeds">How many seeds (≥ 1): seed k derives every invariant's seed from base + k, so seed 0 is exactly the profile's.</param>
    /// <param name="baseSeed">The base seed; default the profile's, else a fresh one (reported in the result).</param>
    /// <param name="declaredOnly">Run only each bug's declared catchers (the fast CI check) instead of every invariant.</param>
    /// <param name="progress">Called after each bug.</param>
    /// <param name="except">Invariant IDs left out (e.g. the conformance ones, to measure what the independent invariants catch).</param>
    /// <returns>The report.</returns>
    /// <exception cref="ArgumentOutOfRangeException"><paramref name="seeds"/> is below 1.</exception>
    public static BiteReport Run(IReadOnlyList<KnownBug> bugs, Profile profile, int seeds = 1, ulong? baseSeed = null, bool declaredOnly = false, Action<BugBite>? progress = null, IReadOnlyCollection<string>? except = null)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(seeds, 1);
        ulong runBase = baseSeed ?? profile.BaseSeed ?? Seed.Fresh().Value;
        var started = System.Diagnostics.Stopwatch.StartNew();
        var columns = declaredOnly
            ? InvariantCatalogue.All.Where(i => bugs.Any(b => b.IsAvailable && b.CaughtBy.Contains(i.Id, StringComparer.OrdinalIgnoreCase))).ToList()
            : [.. InvariantCatalogue.All];
        if (except is { Count: > 0 })
        {
            columns = [.. columns.Where(i => !except.Contains(i.Id, StringComparer.OrdinalIgnoreCase))];
        }
        var rows = new List<BugBite>();
        foreach (var bug in bugs)
        {
            var row = bug.IsAvailable
                ? RunBug(bug, columns.Where(i => !declaredOnly || bug.CaughtBy.Contains(i.Id, StringComparer.OrdinalIgnoreCase)).ToList(), profile, seeds, runBase)
                : new BugBite(bug, BugStatus.Pending, [], [], [], null);
            rows.Add(row);
            progress?.Invoke(row);
        }

        return new BiteReport(profile, runBase, seeds, [.. columns.Select(i => i.Id)], rows, started.Elapsed);
    }

    private static BugBite RunBug(KnownBug bug, IReadOnlyList<Invariant> invariants, Profile profile, int seeds, ulong runBase)
    {
        var impl = PlantedFaults.Create(bug.Fault);
        var caught = new int[invariants.Count];
        var applicable = new bool[invariants.Count];
        var found = new Violation?[invariants.Count];
        var times = new List<TimeSpan?>();
        var cases = new List<int?>();
        BiteExample? example = null;
        for (int k = 0; k < seeds; k++)
        {
            TimeSpan? soonest = null;
            int? soonestCases = null;
            for (int i = 0; i < invariants.Count; i++)
            {
                var invariant = invariants[i];
                var result = invariant.Run(impl, profile.CasesPerInvariant, Seed.Derive(unchecked(runBase + (ulong)k), invariant.Id), maxClasses: 1);
                if (result.Status == ResultStatus.NotTested)
                {
                    continue;
                }

                applicable[i] = true;
                if (result.Status != ResultStatus.Failed)
                {
                    continue;
                }

                caught[i]++;
                found[i] ??= result.Violation;
                var t = result.TimeToFailure ?? result.Elapsed;
                if (soonest is null || t < soonest)
                {
                    soonest = t;
                    soonestCases = result.Cases;
                    if (k == 0 && result.Violation is { } v && result.Replay is { } replay)
                    {
                        example = new BiteExample(invariant.Id, v, replay);
                    }
                }
            }

            times.Add(soonest);
            cases.Add(soonestCases);
        }

        var cells = invariants.Select((inv, i) => new BiteCell(
            inv.Id,
            !applicable[i] ? BiteVerdict.NotApplicable : caught[i] == seeds ? BiteVerdict.Caught : caught[i] > 0 ? BiteVerdict.Sometimes : BiteVerdict.NotCaught,
            caught[i])
        {
            Violation = found[i],
        }).ToList();
        var status = times.All(t => t is not null) ? BugStatus.Caught : BugStatus.Escaped;
        return new BugBite(bug, status, cells, times, cases, example);
    }
}
