using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Judging;

/// <summary>
/// The one place that decides which invariants judge a case of each kind, conformance included, and judges it:
/// verify's failure files, <c>acphys replay</c> and <c>render</c>, corpus replay, fuzz triage and diff case files all
/// ask here, so a case found by any of them is judged the same way everywhere.
/// </summary>
/// <remarks>
/// A walk is judged by its walk invariants, then by the outdoor invariants and OUTSIDE-CELLS-CONFORMANCE on the query of
/// each step as the reference asks it (the queries a correct client asks, one run of the reference per judgement), then
/// by FIND-CELL-CONFORMANCE on the implementation's own walk. A walk that does not start in a land cell is vacuous for
/// the walk invariants (they follow a body on the map; facts §2), never a violation of the reference.
/// </remarks>
public static class Judges
{
    private static readonly IReadOnlyList<Invariant> LandJudges = [.. LandInvariants.All, ConformanceInvariants.LandDefs];
    private static readonly IReadOnlyList<Invariant<OutdoorCase>> StepJudges = [.. OutdoorInvariants.All, ConformanceInvariants.OutsideCells];
    private static readonly IReadOnlyList<Invariant> QueryJudges = [.. StepJudges, ConformanceInvariants.FindCellQuery];
    private static readonly IReadOnlyList<Invariant> WalkJudges = [.. WalkInvariants.All, .. StepJudges, ConformanceInvariants.FindCell];
    private static readonly IReadOnlyList<Invariant> SceneJudges = [.. InvariantCatalogue.SceneInvariants, ConformanceInvariants.FindCell];
    private static readonly IReadOnlyList<Invariant> PartsJudges = [.. PartsInvariants.All];

    /// <summary>Returns the invariants that judge a case kind, in the order they are asked.</summary>
    /// <param name="kind">The kind.</param>
    /// <returns>The invariants.</returns>
    public static IReadOnlyList<Invariant> For(CaseKind kind) => kind.Pick(LandJudges, QueryJudges, WalkJudges, SceneJudges, PartsJudges);

    /// <summary>Returns the case kinds an invariant judges.</summary>
    /// <param name="invariant">The invariant.</param>
    /// <returns>The kinds (every catalogue invariant judges at least one).</returns>
    public static IReadOnlyList<CaseKind> KindsOf(Invariant invariant) =>
        [.. Enum.GetValues<CaseKind>().Where(k => For(k).Contains(invariant))];

    /// <summary>Judges a case with every judge of its kind.</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The case.</param>
    /// <returns>Every verdict.</returns>
    /// <exception cref="AdapterFailureException">The implementation could not answer at all.</exception>
    public static Judgement Judge(ICellPhysics impl, AnyCase c) => new(c, [.. Verdicts(impl, c)]);

    /// <summary>Judges a case until the first violation (the judges after it are not asked).</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The case.</param>
    /// <returns>The first violation in judge order, or null when none.</returns>
    /// <exception cref="AdapterFailureException">The implementation could not answer at all.</exception>
    public static Violation? First(ICellPhysics impl, AnyCase c) =>
        Verdicts(impl, c).FirstOrDefault(v => v.IsViolation) is { } hit ? ViolationOf(hit, c) : null;

    /// <summary>Makes the violation of one violated verdict.</summary>
    /// <param name="verdict">The verdict (violated).</param>
    /// <param name="c">The case it was given on.</param>
    /// <returns>The violation: invariant, message, case and step as fields.</returns>
    public static Violation ViolationOf(Judged verdict, AnyCase c) =>
        new(verdict.Invariant.Id, verdict.Outcome?.Message ?? "violated", c.ToString()) { Case = c, Step = verdict.Outcome?.Step };

    private static IEnumerable<Judged> Verdicts(ICellPhysics impl, AnyCase c) => c.Match(
        land => Each(impl, LandInvariants.All.Append(ConformanceInvariants.LandDefs), land.Case),
        q => Each(impl, StepJudges.Append(ConformanceInvariants.FindCellQuery), q.Query),
        w => WalkVerdicts(impl, w),
        sw => Each(impl, InvariantCatalogue.SceneInvariants, sw.Walk).Append(One(impl, ConformanceInvariants.FindCell, new AnyWalk(null, sw.Walk))),
        p => Each(impl, PartsInvariants.All, p.Parts));

    private static IEnumerable<Judged> WalkVerdicts(ICellPhysics impl, AnyCase.OutdoorWalk w)
    {
        string? unjudgeable = w.Unjudgeable;
        foreach (var invariant in WalkInvariants.All)
        {
            yield return unjudgeable is null ? One(impl, invariant, w.Walk) : new Judged(invariant, Outcome.Vacuous, unjudgeable);
        }

        IReadOnlyList<WalkStep>? steps = null;
        foreach (var invariant in StepJudges)
        {
            if (invariant.WhyNotTestable(impl) is string why)
            {
                yield return new Judged(invariant, null, why);
                continue;
            }

            steps ??= WalkRunner.Run(ReferenceAdapter.Instance, w.Walk);
            yield return new Judged(invariant, AtFirstViolatingStep(invariant, impl, steps), null);
        }

        yield return One(impl, ConformanceInvariants.FindCell, new AnyWalk(w.Walk, null));
    }

    // One per-step invariant over a walk's queries: its first violation, at its step; else holds when some step held.
    private static Outcome AtFirstViolatingStep(Invariant<OutdoorCase> invariant, ICellPhysics impl, IReadOnlyList<WalkStep> steps)
    {
        bool held = false;
        foreach (var step in steps)
        {
            var o = invariant.Check(impl, step.Query);
            if (o.IsViolation)
            {
                return Outcome.ViolatedAt(step.Index, $"step {step.Index}: {o.Message}");
            }

            held |= o.Verdict == Verdict.Holds;
        }

        return held ? Outcome.Holds : Outcome.Vacuous;
    }

    private static IEnumerable<Judged> Each<TCase>(ICellPhysics impl, IEnumerable<Invariant<TCase>> invariants, TCase c) =>
        invariants.Select(i => One(impl, i, c));

    private static Judged One<TCase>(ICellPhysics impl, Invariant<TCase> invariant, TCase c) =>
        invariant.WhyNotTestable(impl) is string why ? new Judged(invariant, null, why) : new Judged(invariant, invariant.Check(impl, c), null);
}
