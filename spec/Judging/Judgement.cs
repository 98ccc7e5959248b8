using AcPhys.Formats.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Judging;

/// <summary>Every judge's verdict on one case (<see cref="Judges.Judge"/>), in the order <see cref="Judges.For"/> lists them.</summary>
/// <param name="Case">The case.</param>
/// <param name="Verdicts">One per judge of the case's kind.</param>
public sealed record Judgement(AnyCase Case, IReadOnlyList<Judged> Verdicts)
{
    /// <summary>Gets the violations, in judge order, each with the case, the invariant and its step.</summary>
    public IReadOnlyList<Violation> Violations => [.. Verdicts.Where(v => v.IsViolation).Select(v => Judges.ViolationOf(v, Case))];

    /// <summary>Gets a value indicating whether some judge was violated.</summary>
    public bool IsViolation => Verdicts.Any(v => v.IsViolation);

    /// <summary>Gets the IDs of the violated invariants.</summary>
    public IReadOnlyList<string> ViolatedIds => [.. Verdicts.Where(v => v.IsViolation).Select(v => v.Invariant.Id)];

    /// <summary>Gets the first step with a violation (a violation of a whole walk at no one step counts as its last step), or null.</summary>
    /// <param name="lastStep">The walk's last step index (0 for a case that is not a walk).</param>
    /// <returns>The step, or null when nothing is violated.</returns>
    public int? FirstViolatingStep(int lastStep) =>
        Verdicts.Where(v => v.IsViolation).Select(v => Math.Clamp(v.Outcome!.Value.Step ?? lastStep, 0, lastStep)).Order().Cast<int?>().FirstOrDefault();
}
