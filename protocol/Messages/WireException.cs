namespace AcPhys.Protocol.Messages;

/// <summary>A protocol message that is not valid protocol v1: not JSON, not an object, a missing or mistyped field.</summary>
public sealed class WireException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">What is wrong with the message.</param>
    public WireException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    public WireException()
    {
    }

    /// <summary>Initializes a new instance with a cause.</summary>
    /// <param name="message">What is wrong.</param>
    /// <param name="inner">The cause.</param>
    public WireException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
