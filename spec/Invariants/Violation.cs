using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>A broken invariant on a concrete case.</summary>
/// <param name="InvariantId">The invariant's stable ID.</param>
/// <param name="Message">Observed against expected.</param>
/// <param name="CaseText">The case, printed in its one-line replayable form.</param>
public sealed record Violation(string InvariantId, string Message, string CaseText)
{
    /// <summary>Gets the case itself, when known, so it can be written to a file and judged again.</summary>
    public AnyCase? Case { get; init; }

    /// <summary>Gets the step of a walk the violation is at (0: the start), or null when it is not at one step.</summary>
    public int? Step { get; init; }

    /// <summary>Formats the violation on one line.</summary>
    /// <returns>The text.</returns>
    public override string ToString() => $"{InvariantId}: {Message} [{CaseText}]";
}

/// <summary>Thrown by harnesses (the fuzzer) when an invariant is broken; carries the invariant ID.</summary>
public sealed class InvariantViolationException : Exception
{
    /// <summary>Initializes a new instance from a violation.</summary>
    /// <param name="violation">The violation.</param>
    public InvariantViolationException(Violation violation)
        : base(violation.ToString()) => Violation = violation;

    /// <summary>Initializes a new instance.</summary>
    public InvariantViolationException()
        : this(new Violation("UNKNOWN", "unspecified", string.Empty))
    {
    }

    /// <summary>Initializes a new instance with a message.</summary>
    /// <param name="message">The message.</param>
    public InvariantViolationException(string message)
        : this(new Violation("UNKNOWN", message, string.Empty))
    {
    }

    /// <summary>Initializes a new instance with a message and a cause.</summary>
    /// <param name="message">The message.</param>
    /// <param name="inner">The cause.</param>
    public InvariantViolationException(string message, Exception inner)
        : base(message, inner) => Violation = new Violation("UNKNOWN", message, string.Empty);

    /// <summary>Gets the violation.</summary>
    public Violation Violation { get; }

    /// <summary>Gets the broken invariant's ID.</summary>
    public string InvariantId => Violation.InvariantId;
}
