namespace AcPhys.Cli;

/// <summary>Bad input the user can fix (an unknown ID, a malformed seed, ...): reported on one line, exit 2, no stack trace.</summary>
internal class UsageException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">What is wrong, for a person; one line.</param>
    public UsageException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    public UsageException()
    {
    }

    /// <summary>Initializes a new instance with a cause.</summary>
    /// <param name="message">What is wrong.</param>
    /// <param name="inner">The cause.</param>
    public UsageException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
