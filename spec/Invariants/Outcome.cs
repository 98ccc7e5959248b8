namespace AcPhys.Spec.Invariants;

/// <summary>What one check said about one case.</summary>
public enum Verdict
{
    /// <summary>The invariant applied to the case and held.</summary>
    Holds,

    /// <summary>The case is outside the invariant's premise (counted, so vacuous runs are visible).</summary>
    Vacuous,

    /// <summary>The invariant applied and was broken.</summary>
    Violated,
}

/// <summary>The result of checking one invariant on one case.</summary>
/// <param name="Verdict">Held, vacuous or violated.</param>
/// <param name="Message">For a violation, what was observed against what was expected; for a vacuous case, why it could not be judged (or null).</param>
public readonly record struct Outcome(Verdict Verdict, string? Message)
{
    /// <summary>Gets the outcome "applied and held".</summary>
    public static Outcome Holds => new(Verdict.Holds, null);

    /// <summary>Gets the outcome "did not apply".</summary>
    public static Outcome Vacuous => new(Verdict.Vacuous, null);

    /// <summary>Returns "did not apply" with the reason (e.g. an answer field the implementation does not send), so a run in
    /// which no case applied can say why it tested nothing (issue #29).</summary>
    /// <param name="why">Why the case could not be judged.</param>
    /// <returns>The outcome.</returns>
    public static Outcome VacuousBecause(string why) => new(Verdict.Vacuous, why);

    /// <summary>Returns a violation.</summary>
    /// <param name="message">Observed against expected.</param>
    /// <returns>The outcome.</returns>
    public static Outcome Violated(string message) => new(Verdict.Violated, message);

    /// <summary>Returns a violation at one step of a walk (the message says so in its own words too).</summary>
    /// <param name="step">The step index (0: the start).</param>
    /// <param name="message">Observed against expected.</param>
    /// <returns>The outcome.</returns>
    public static Outcome ViolatedAt(int step, string message) => new(Verdict.Violated, message) { Step = step };

    /// <summary>Gets the step of a walk the violation is at, or null when it is not at one step (or the case is not a walk).</summary>
    public int? Step { get; init; }

    /// <summary>Gets a value indicating whether this is a violation.</summary>
    public bool IsViolation => Verdict == Verdict.Violated;
}
