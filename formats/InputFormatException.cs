namespace AcPhys.Formats;

/// <summary>
/// An input that is not valid — a corpus or failure file, a scene (JSON, or as retail dat records and their manifest):
/// the message names the source, the place (JSON path, or record, field and byte offset) and what is wrong. The input is
/// refused whole. One type for every format of this assembly (issue 42: it was three, and eight catch sites translated
/// one into another with the same message).
/// </summary>
public sealed class InputFormatException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">Source, place and problem.</param>
    public InputFormatException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    public InputFormatException()
    {
    }

    /// <summary>Initializes a new instance with a cause.</summary>
    /// <param name="message">Source, place and problem.</param>
    /// <param name="inner">The cause.</param>
    public InputFormatException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
