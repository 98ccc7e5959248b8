using System.Globalization;
using AcPhys.Protocol.Messages;

namespace AcPhys.Protocol.Child;

/// <summary>A protocol peer sent a line longer than the limit (<see cref="BoundedLineReader"/>); the message names the limit, never the line.</summary>
internal sealed class LineTooLongException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="limit">The limit in bytes.</param>
    public LineTooLongException(int limit)
        : base(string.Create(CultureInfo.InvariantCulture, $"line longer than {limit:N0} bytes, the limit (set {LineLimit.Variable} to change it)"))
    {
        Limit = limit;
    }

    /// <summary>Initializes a new instance.</summary>
    public LineTooLongException()
    {
    }

    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">The message.</param>
    public LineTooLongException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">The message.</param>
    /// <param name="inner">The cause.</param>
    public LineTooLongException(string message, Exception inner)
        : base(message, inner)
    {
    }

    /// <summary>Gets the limit in bytes.</summary>
    public int Limit { get; }
}
