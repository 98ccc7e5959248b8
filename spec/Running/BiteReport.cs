using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Running;

/// <summary>What one invariant did against one catalogue bug, over every seed of a bite run.</summary>
public enum BiteVerdict
{
    /// <summary>It found a violation under every seed.</summary>
    Caught,

    /// <summary>It found a violation under some seeds, not all.</summary>
    Sometimes,

    /// <summary>It held under every seed.</summary>
    NotCaught,

    /// <summary>The faulty implementation lacks an operation it needs (or declares another pick).</summary>
    NotApplicable,
}

/// <summary>How a catalogue bug fared as a whole.</summary>
public enum BugStatus
{
    /// <summary>Some invariant caught it under every seed.</summary>
    Caught,

    /// <summary>Under at least one seed no invariant caught it.</summary>
    Escaped,

    /// <summary>Its fault does not exist yet (an entry waiting for another branch); not run.</summary>
    Pending,
}

/// <summary>One cell of the bite matrix.</summary>
/// <param name="InvariantId">The invariant.</param>
/// <param name="Verdict">The verdict over all seeds.</param>
/// <param name="SeedsCaught">Under how many seeds it caught the bug.</param>
public sealed record BiteCell(string InvariantId, BiteVerdict Verdict, int SeedsCaught)
{
    /// <summary>Gets the violation of the first seed that caught the bug (shrunk, with its case), or null when none did.</summary>
    public Violation? Violation { get; init; }
}

/// <summary>The first catch of a bug: which invariant, its shrunk violation and the seed that replays it.</summary>
/// <param name="InvariantId">The invariant that caught it soonest under the first seed.</param>
/// <param name="Violation">The shrunk violation.</param>
/// <param name="Replay">The seed (with size) that replays the failing case.</param>
public sealed record BiteExample(string InvariantId, Violation Violation, Seed Replay);

/// <summary>One row of the bite matrix.</summary>
/// <param name="Bug">The catalogue entry.</param>
/// <param name="Status">Caught, escaped or pending.</param>
/// <param name="Cells">One cell per invariant run (empty when pending).</param>
/// <param name="TimeToDetect">Per seed: the soonest time any invariant reached a violating case, or null when none did.</param>
/// <param name="CasesToDetect">Per seed: the generated cases the soonest catcher needed, or null.</param>
/// <param name="Example">The first catch under the first seed, or null.</param>
public sealed record BugBite(KnownBug Bug, BugStatus Status, IReadOnlyList<BiteCell> Cells, IReadOnlyList<TimeSpan?> TimeToDetect, IReadOnlyList<int?> CasesToDetect, BiteExample? Example)
{
    /// <summary>Gets the median time to detect over the seeds that caught it, or null.</summary>
    public TimeSpan? Median => BiteStats.Median(TimeToDetect.OfType<TimeSpan>().ToList());

    /// <summary>Gets the longest time to detect over the seeds that caught it, or null.</summary>
    public TimeSpan? Max => TimeToDetect.OfType<TimeSpan>().Select(t => (TimeSpan?)t).Max();

    /// <summary>Gets the invariants that caught it under every seed.</summary>
    public IEnumerable<string> CaughtBy => Cells.Where(c => c.Verdict == BiteVerdict.Caught).Select(c => c.InvariantId);

    /// <summary>Gets the declared catchers that did not catch it under every seed.</summary>
    public IEnumerable<string> MissedDeclared => Status == BugStatus.Pending ? [] : Bug.CaughtBy.Where(id => !CaughtBy.Contains(id));
}

/// <summary>A whole bite run: every catalogue bug against every invariant.</summary>
/// <param name="Profile">The profile (cases per invariant).</param>
/// <param name="BaseSeed">The base seed; seed k of the run derives each invariant's seed from <c>BaseSeed + k</c>.</param>
/// <param name="Seeds">How many seeds.</param>
/// <param name="InvariantIds">The invariants run, in catalogue order (the matrix columns).</param>
/// <param name="Bugs">The rows.</param>
/// <param name="Elapsed">Wall time of the run.</param>
public sealed record BiteReport(Profile Profile, ulong BaseSeed, int Seeds, IReadOnlyList<string> InvariantIds, IReadOnlyList<BugBite> Bugs, TimeSpan Elapsed)
{
    /// <summary>Gets the bugs no invariant caught under some seed.</summary>
    public IEnumerable<BugBite> Escaped => Bugs.Where(b => b.Status == BugStatus.Escaped);

    /// <summary>Gets the bugs waiting for their fault.</summary>
    public IEnumerable<BugBite> Pending => Bugs.Where(b => b.Status == BugStatus.Pending);

    /// <summary>Gets the bugs that were run.</summary>
    public IEnumerable<BugBite> Run => Bugs.Where(b => b.Status != BugStatus.Pending);
}

/// <summary>Small statistics over detection times.</summary>
public static class BiteStats
{
    /// <summary>Returns the median (the mean of the middle two for an even count), or null for none.</summary>
    /// <param name="times">The times.</param>
    /// <returns>The median.</returns>
    public static TimeSpan? Median(IReadOnlyCollection<TimeSpan> times)
    {
        if (times.Count == 0)
        {
            return null;
        }

        var sorted = times.Order().ToArray();
        int mid = sorted.Length / 2;
        return sorted.Length % 2 == 1 ? sorted[mid] : (sorted[mid - 1] + sorted[mid]) / 2;
    }
}
