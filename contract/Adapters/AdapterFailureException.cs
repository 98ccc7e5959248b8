namespace AcPhys.Contract;

/// <summary>
/// Thrown by an adapter when the implementation behind it cannot answer at all (it crashed, hung past its timeout,
/// or spoke garbage). Distinct from a wrong answer: runners turn it into a tool error (exit 2), not a violation.
/// </summary>
public sealed class AdapterFailureException : Exception
{
    /// <summary>Initializes a new instance with a message.</summary>
    /// <param name="message">What went wrong, for a person.</param>
    public AdapterFailureException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance with a message and a cause.</summary>
    /// <param name="message">What went wrong, for a person.</param>
    /// <param name="inner">The underlying exception.</param>
    public AdapterFailureException(string message, Exception inner)
        : base(message, inner)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    public AdapterFailureException()
    {
    }
}
