namespace AcPhys.Formats.Corpus;

/// <summary>A corpus (or other input) file that is not valid: the message names the file, the JSON path and what is wrong.</summary>
public sealed class CorpusFormatException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">File, path and problem.</param>
    public CorpusFormatException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    public CorpusFormatException()
    {
    }

    /// <summary>Initializes a new instance with a cause.</summary>
    /// <param name="message">File, path and problem.</param>
    /// <param name="inner">The cause.</param>
    public CorpusFormatException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
