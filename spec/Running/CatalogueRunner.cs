using System.Diagnostics;
using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Invariants;
using FsCheck;
using FsCheck.Fluent;
using Outcome = AcPhys.Spec.Invariants.Outcome;

namespace AcPhys.Spec.Running;

/// <summary>
/// Runs invariants against an implementation with FsCheck: generated cases from a seed, shrinking on failure,
/// the boundary-class distribution, and the seed that replays a failure.
/// </summary>
public static class CatalogueRunner
{
    /// <summary>Runs one invariant over its case domain.</summary>
    /// <param name="invariant">The invariant.</param>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="cases">How many cases to generate.</param>
    /// <param name="seed">The seed (with a size to replay one case).</param>
    /// <param name="sink">Optional sink for FsCheck's own text (the class distribution).</param>
    /// <param name="maxClasses">How many failure classes to search for; 1 stops at the first failure (a bite check needs no more, and a walk invariant's further search is its costliest part).</param>
    /// <returns>The result.</returns>
    /// <exception cref="AdapterFailureException">The implementation could not answer at all.</exception>
    /// <typeparam name="TCase">The case type.</typeparam>
    public static InvariantResult Run<TCase>(Invariant<TCase> invariant, ICellPhysics impl, int cases, Seed seed, Action<string>? sink = null, int maxClasses = MaxClasses)
    {
        if (impl is not ITransport { Streams: true } transport)
        {
            return RunClasses(invariant, impl, cases, seed, sink, maxClasses);
        }

        // A child that pipelines: the run is speculated and streamed, and replayed only when an answer differs
        // (ITransport.Streamed); the class distribution of the run that stands is the one passed on.
        var wall = Stopwatch.StartNew();
        List<string>? said = null;
        var result = transport.Streamed(() =>
        {
            said = sink is null ? null : [];
            return RunClasses(invariant, impl, cases, seed, said is null ? null : said.Add, maxClasses);
        });
        foreach (string line in said ?? [])
        {
            sink!(line);
        }

        return result with { Elapsed = wall.Elapsed };
    }

    private static InvariantResult RunClasses<TCase>(Invariant<TCase> invariant, ICellPhysics impl, int cases, Seed seed, Action<string>? sink, int maxClasses)
    {
        var first = RunOnce(invariant, impl, cases, seed, [], sink);
        if (first.Status != ResultStatus.Failed || Typed<TCase>(first.Violation?.Case) is not TCase shrunk)
        {
            return first;
        }

        // Keep searching within the same budget (issue #18: a second bug behind the first must not stay hidden):
        // each further search treats violations of the classes already reported as seen, so it fails, and shrinks,
        // only on a new class.
        var domain = invariant.Domain;
        var known = new List<string> { domain.Primary(shrunk) };
        var more = new List<ClassFailure>();
        int used = first.Cases;
        var elapsed = first.Elapsed;
        for (int round = 1; round < maxClasses && used < cases; round++)
        {
            var next = Seed.Derive(seed.Value, "class-" + round);
            var again = RunOnce(invariant, impl, cases - used, next, known, null);
            used += Math.Max(again.Cases, 1);
            elapsed += again.Elapsed;
            if (again.Status != ResultStatus.Failed || again.Violation is not { } v || Typed<TCase>(v.Case) is not TCase c)
            {
                break;
            }

            string cls = domain.Primary(c);
            if (known.Contains(cls))
            {
                break; // shrinking came back to a reported class: nothing new within reach
            }

            known.Add(cls);
            more.Add(new ClassFailure(cls, v, again.Replay ?? next));
        }

        return first with { FailureClass = known[0], MoreFailures = more, Elapsed = elapsed };
    }

    /// <summary>How many distinct failure classes one invariant reports at most.</summary>
    public const int MaxClasses = 4;

    private static InvariantResult RunOnce<TCase>(Invariant<TCase> invariant, ICellPhysics impl, int cases, Seed seed, IReadOnlyList<string> excluded, Action<string>? sink)
    {
        if (invariant.WhyNotTestable(impl) is string reason)
        {
            return new InvariantResult
            {
                Invariant = invariant,
                Status = ResultStatus.NotTested,
                NotTestedReason = reason,
                Seed = seed,
            };
        }

        var stopwatch = Stopwatch.StartNew();
        var classes = new Dictionary<string, int>();
        int generated = 0, applicable = 0;
        string? vacuousWhy = null;
        bool failing = false;
        TimeSpan? timeToFailure = null;
        Violation? firstSeen = null;
        AdapterFailureException? adapterFailure = null;

        var domain = invariant.Domain;
        Property Body(TCase c)
        {
            Outcome outcome;
            try
            {
                outcome = Check(invariant, impl, c, excluded);
            }
            catch (AdapterFailureException e)
            {
                adapterFailure ??= e;
                throw;
            }

            if (!failing)
            {
                generated++;
                if (outcome.Verdict != Verdict.Vacuous)
                {
                    applicable++;
                }
                else
                {
                    vacuousWhy ??= outcome.Message;
                }

                foreach (var tag in domain.Classes(c))
                {
                    classes[tag] = classes.GetValueOrDefault(tag) + 1;
                }

                failing = outcome.IsViolation;
                if (failing)
                {
                    timeToFailure = stopwatch.Elapsed;
                    firstSeen = new Violation(invariant.Id, outcome.Message ?? "violated", c?.ToString() ?? string.Empty) { Case = AnyCase.Of(c), Step = outcome.Step };
                }
            }

            var property = (!outcome.IsViolation).Label(outcome.Message ?? invariant.Id);

            // The stamp only feeds FsCheck's own text, which goes to the sink: with none it is not made (issue 51: FsCheck
            // formats a collected value by reflection, a tenth of a scene invariant's time), and no verdict reads it.
            return sink is null ? property : property
                .Collect(domain.Primary(c) + (outcome.Verdict == Verdict.Vacuous ? " (vacuous)" : string.Empty));
        }

        var runner = new CapturingRunner(sink);
        var config = CaseSweep.ConfigFor(invariant.Id, cases, seed, runner);
        FsCheck.Check.One(config, Prop.ForAll(domain.Arbitrary, (Func<TCase, Property>)Body));
        stopwatch.Stop();

        if (adapterFailure is not null)
        {
            throw adapterFailure;
        }

        var result = new InvariantResult
        {
            Invariant = invariant,
            Status = ResultStatus.Passed,
            Cases = generated,
            Applicable = applicable,
            Classes = classes,
            Seed = seed,
            Elapsed = stopwatch.Elapsed,
        };

        if (runner.Result is TestResult.Failed failed)
        {
            var original = failed.Item2.Head is TCase o ? ViolationOf(invariant, impl, o, excluded) : null;
            var shrunk = failed.Item3.Head is TCase s ? ViolationOf(invariant, impl, s, excluded) : null;
            if (original is null && shrunk is null && firstSeen is not null)
            {
                // A violation was seen but does not come back on re-check: the implementation keeps state between
                // calls (e.g. a cell array never reset) or is non-deterministic. That is a finding, reported as seen.
                original = firstSeen with { Message = firstSeen.Message + " (not reproducible on re-check: the implementation keeps state between calls or is non-deterministic)" };
            }

            if (original is null && shrunk is null)
            {
                // The property itself threw (a tool defect, not an implementation finding): say so, never an empty violation.
                string why = failed.Item4 is FsCheck.Outcome.Failed f ? f.Item.ToString() : "no violation on re-check (non-deterministic implementation?)";
                throw new InvalidOperationException($"{invariant.Id}: the property failed without a reproducible violation on {failed.Item3.Head}: {why}");
            }

            return result with
            {
                Status = ResultStatus.Failed,
                TimeToFailure = timeToFailure,
                Violation = shrunk ?? original,
                Original = original,
                Replay = new Seed(failed.Item6.Seed, failed.Item6.Gamma, failed.Item7),
            };
        }

        // Never PASS with nothing checked (issue #29): no generated case could judge the invariant.
        return applicable > 0 ? result : result with
        {
            Status = ResultStatus.NotTested,
            NotTestedReason = $"none of the {generated} generated cases could judge it" + (vacuousWhy is null ? string.Empty : $" ({vacuousWhy})"),
        };
    }

    /// <summary>Runs every invariant of the catalogue under a profile.</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="profile">The budget.</param>
    /// <param name="only">Invariant IDs to run (all when null or empty).</param>
    /// <param name="fixedSeed">A seed to use for every invariant instead of the profile's.</param>
    /// <param name="maxClasses">Failure classes each failing invariant searches for (1: stop at its first failure).</param>
    /// <param name="progress">Called after each invariant.</param>
    /// <returns>One result per invariant.</returns>
    public static IReadOnlyList<InvariantResult> RunCatalogue(
        ICellPhysics impl,
        Profile profile,
        IReadOnlyCollection<string>? only = null,
        Seed? fixedSeed = null,
        int maxClasses = MaxClasses,
        Action<InvariantResult>? progress = null) =>
        RunCatalogue(impl, profile, CatalogueWorkers.One, only, fixedSeed, maxClasses, progress);

    /// <summary>Runs every invariant of the catalogue under a profile, on one thread or several (<see cref="CatalogueWorkers"/>).</summary>
    /// <param name="impl">The implementation under test (the caller's thread asks it).</param>
    /// <param name="profile">The budget.</param>
    /// <param name="workers">The threads, and the implementation each extra one asks.</param>
    /// <param name="only">Invariant IDs to run (all when null or empty).</param>
    /// <param name="fixedSeed">A seed to use for every invariant instead of the profile's.</param>
    /// <param name="maxClasses">Failure classes each failing invariant searches for (1: stop at its first failure).</param>
    /// <param name="progress">Called after each invariant, in catalogue order.</param>
    /// <returns>One result per invariant, in catalogue order: the same on any number of threads.</returns>
    internal static IReadOnlyList<InvariantResult> RunCatalogue(
        ICellPhysics impl,
        Profile profile,
        CatalogueWorkers workers,
        IReadOnlyCollection<string>? only = null,
        Seed? fixedSeed = null,
        int maxClasses = MaxClasses,
        Action<InvariantResult>? progress = null)
    {
        ulong runBase = profile.BaseSeed ?? Seed.Fresh().Value;
        var chosen = InvariantCatalogue.All.Where(i => only is not { Count: > 0 } || only.Contains(i.Id, StringComparer.OrdinalIgnoreCase)).ToList();
        if (workers.Count > 1 && chosen.Count > 1)
        {
            return ConcurrentCatalogue.Run(chosen, impl, workers, (invariant, mine) => RunInvariant(invariant, mine, profile, runBase, fixedSeed, maxClasses), progress);
        }

        var results = new List<InvariantResult>();
        foreach (var invariant in chosen)
        {
            var result = RunInvariant(invariant, impl, profile, runBase, fixedSeed, maxClasses);
            results.Add(result);
            progress?.Invoke(result);
        }

        return results;
    }

    /// <summary>
    /// Runs one invariant of the catalogue as <see cref="RunCatalogue(ICellPhysics, Profile, IReadOnlyCollection{string}?, Seed?, int, Action{InvariantResult}?)"/> does: its seed derived from the run's base seed
    /// and its ID (or the fixed seed), the profile's cases, then the exhaustive sweep of a LandDefs invariant that passed
    /// when the profile sweeps and no seed is fixed. The gate as xunit tests (AcPhys.Xunit) runs each invariant through
    /// this, so its verdicts are <c>acphys verify</c>'s.
    /// </summary>
    /// <param name="invariant">The invariant.</param>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="profile">The budget.</param>
    /// <param name="runBase">The run's base seed (the profile's, or a fresh one printed by the caller).</param>
    /// <param name="fixedSeed">A seed to use instead of the derived one (no sweep then).</param>
    /// <param name="maxClasses">Failure classes a failing invariant searches for.</param>
    /// <returns>The result.</returns>
    /// <exception cref="AdapterFailureException">The implementation could not answer at all.</exception>
    public static InvariantResult RunInvariant(Invariant invariant, ICellPhysics impl, Profile profile, ulong runBase, Seed? fixedSeed = null, int maxClasses = MaxClasses)
    {
        var seed = fixedSeed ?? Seed.Derive(runBase, invariant.Id);
        var result = invariant.Run(impl, profile.CasesPerInvariant, seed, maxClasses: maxClasses);
        if (profile.Exhaustive && result.Status == ResultStatus.Passed && fixedSeed is null && invariant is Invariant<LandCase> land)
        {
            var sweep = Transports.Streamed(impl, () => Exhaustive.For(land, impl)); // --sweeps served: streamed too
            if (sweep is not null)
            {
                result = result with
                {
                    ExhaustiveCases = sweep.Cases,
                    Status = sweep.FirstViolation is null ? ResultStatus.Passed : ResultStatus.Failed,
                    Violation = sweep.FirstViolation,
                    Original = sweep.FirstViolation,
                    Elapsed = result.Elapsed + sweep.Elapsed,
                };
            }
        }

        return result;
    }

    // A violation of an excluded (already reported) class counts as holding, so a further search fails only on a new class.
    private static Outcome Check<TCase>(Invariant<TCase> invariant, ICellPhysics impl, TCase c, IReadOnlyList<string> excluded)
    {
        var outcome = invariant.Check(impl, c);
        return outcome.IsViolation && excluded.Count > 0 && excluded.Contains(invariant.Domain.Primary(c)) ? Outcome.Holds : outcome;
    }

    private static Violation? ViolationOf<TCase>(Invariant<TCase> invariant, ICellPhysics impl, TCase c, IReadOnlyList<string> excluded)
    {
        var outcome = Check(invariant, impl, c, excluded);
        return outcome.IsViolation ? new Violation(invariant.Id, outcome.Message ?? "violated", c?.ToString() ?? string.Empty) { Case = AnyCase.Of(c), Step = outcome.Step } : null;
    }

    // The stored case back as the invariant's case type (a stored walk of either kind is an AnyWalk again), so an
    // invariant over AnyWalk (FIND-CELL-CONFORMANCE) keeps searching for further failure classes as every other does.
    private static object? Typed<TCase>(AnyCase? stored) => stored switch
    {
        { Value: TCase value } => value,
        AnyCase.OutdoorWalk w when typeof(TCase) == typeof(AnyWalk) => new AnyWalk(w.Walk, null),
        AnyCase.WalkInScene sw when typeof(TCase) == typeof(AnyWalk) => new AnyWalk(null, sw.Walk),
        _ => null,
    };
}
