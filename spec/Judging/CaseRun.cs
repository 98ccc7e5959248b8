using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Judging;

/// <summary>
/// A case run on one implementation, as replay and render show it: the judgement, the implementation's own steps (for
/// a walk or a scene walk; empty for a single query) and each violation filed under its step.
/// </summary>
/// <param name="Judgement">Every judge's verdict.</param>
/// <param name="Trace">The implementation's steps: one for the start and one per step (empty when the case is not a walk, or the implementation cannot walk it).</param>
/// <param name="PerStep">The violations under each step of <paramref name="Trace"/> (a whole-walk violation at no one step goes under the last); one list holding every violation when there is no trace.</param>
public sealed record CaseRun(Judgement Judgement, IReadOnlyList<WalkStep> Trace, IReadOnlyList<IReadOnlyList<Violation>> PerStep)
{
    /// <summary>Gets the index of the first step with a violation, or null.</summary>
    public int? FirstViolatingStep => PerStep.Select((v, i) => (v, i)).FirstOrDefault(t => t.v.Count > 0) is { v: not null } hit ? hit.i : null;

    /// <summary>Gets the number of invariants violated.</summary>
    public int ViolatedCount => Judgement.ViolatedIds.Count;

    /// <summary>Runs and judges a case.</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The case.</param>
    /// <returns>The run.</returns>
    /// <exception cref="AdapterFailureException">The implementation could not answer at all.</exception>
    public static CaseRun Of(ICellPhysics impl, AnyCase c)
    {
        var judgement = Judges.Judge(impl, c);
        var trace = TraceOf(impl, c);
        int slots = Math.Max(trace.Count, 1);
        var perStep = Enumerable.Range(0, slots).Select(_ => new List<Violation>()).ToList();
        foreach (var v in judgement.Violations)
        {
            perStep[Math.Clamp(v.Step ?? (slots - 1), 0, slots - 1)].Add(v);
        }

        return new CaseRun(judgement, trace, perStep);
    }

    // The implementation's own walk, to show; a walk it cannot take (an operation missing, or it throws: a violation
    // the judges report) shows no steps.
    private static IReadOnlyList<WalkStep> TraceOf(ICellPhysics impl, AnyCase c)
    {
        try
        {
            return c switch
            {
                AnyCase.OutdoorWalk w when (impl.Ops & Op.FindCell) != 0 => WalkRunner.Run(impl, w.Walk),
                AnyCase.WalkInScene sw when SceneQueryKinds.OffersScenes(impl.Ops) => SceneWalkRunner.Run(impl, sw.Walk),
                _ => [],
            };
        }
        catch (Exception e) when (e is not AdapterFailureException)
        {
            return [];
        }
    }
}
