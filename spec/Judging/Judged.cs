using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Judging;

/// <summary>One invariant's verdict on one case.</summary>
/// <param name="Invariant">The invariant.</param>
/// <param name="Outcome">Its outcome (a violation at one step of a walk carries the step), or null when it was not tested.</param>
/// <param name="Reason">Why it was not tested, or why it was vacuous without being asked (a walk the reference cannot judge); else null.</param>
public sealed record Judged(Invariant Invariant, Outcome? Outcome, string? Reason)
{
    /// <summary>Gets a value indicating whether the invariant was violated.</summary>
    public bool IsViolation => Outcome is { IsViolation: true };
}
