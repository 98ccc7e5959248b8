namespace AcPhys.Contract;

/// <summary>
/// A query the tool cannot put to an implementation exactly in the form it asked for (a world-frame port, issue #29:
/// a centre whose world coordinate a double cannot carry). The case is not judged — NOT a failure of the
/// implementation — and the invariant counts it as not applicable with this message as the reason.
/// </summary>
public sealed class UnposableQueryException : Exception
{
    /// <summary>Initializes a new instance of the <see cref="UnposableQueryException"/> class.</summary>
    public UnposableQueryException()
    {
    }

    /// <summary>Initializes a new instance of the <see cref="UnposableQueryException"/> class.</summary>
    /// <param name="message">Why the query cannot be put.</param>
    public UnposableQueryException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance of the <see cref="UnposableQueryException"/> class.</summary>
    /// <param name="message">Why the query cannot be put.</param>
    /// <param name="inner">The cause.</param>
    public UnposableQueryException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
