namespace AcPhys.Formats.Scenes;

/// <summary>A scene that is not valid: the message names the source, the JSON path and what is wrong. The scene is refused whole.</summary>
public sealed class SceneFormatException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">Source, path and problem.</param>
    public SceneFormatException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance.</summary>
    public SceneFormatException()
    {
    }

    /// <summary>Initializes a new instance with a cause.</summary>
    /// <param name="message">Source, path and problem.</param>
    /// <param name="inner">The cause.</param>
    public SceneFormatException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
