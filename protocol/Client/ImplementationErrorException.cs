namespace AcPhys.Protocol.Client;

/// <summary>
/// An implementation answered <c>{"error": ...}</c> to an operation it announced. The operations are total, so this is
/// a finding (the invariant reports it as a violation), not a tool error.
/// </summary>
internal sealed class ImplementationErrorException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">The op and the implementation's error text.</param>
    public ImplementationErrorException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    public ImplementationErrorException()
    {
    }

    /// <summary>Initializes a new instance with a cause.</summary>
    /// <param name="message">The message.</param>
    /// <param name="inner">The cause.</param>
    public ImplementationErrorException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
