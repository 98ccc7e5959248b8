namespace AcPhys.Fuzz.Targets;

/// <summary>Thrown by a parser target when an accepted input does not come back the same after write → read → write.</summary>
public sealed class RoundTripException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    public RoundTripException()
    {
    }

    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">The two texts.</param>
    public RoundTripException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">The message.</param>
    /// <param name="inner">The cause.</param>
    public RoundTripException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
