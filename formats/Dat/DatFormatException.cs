namespace AcPhys.Formats.Dat;

/// <summary>
/// A record folder or a record that is not valid: the message names the record (or manifest), the field and the byte
/// offset. The whole scene is refused.
/// </summary>
public sealed class DatFormatException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">Record, field, offset and problem.</param>
    public DatFormatException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    public DatFormatException()
    {
    }

    /// <summary>Initializes a new instance with a cause.</summary>
    /// <param name="message">Record, field, offset and problem.</param>
    /// <param name="inner">The cause.</param>
    public DatFormatException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
