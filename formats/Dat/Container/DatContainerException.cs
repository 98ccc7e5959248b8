using System.Globalization;

namespace AcPhys.Formats.Dat.Container;

/// <summary>
/// A dat container (docs/dat-container.md) that cannot be read: truncated, a block chain that loops or runs past the
/// end, a directory that loops or is too deep, sizes that disagree, or a record inside it that the record reader
/// refuses. The message names the file, the object id (when one is being read) and the file offset.
/// </summary>
public sealed class DatContainerException : Exception
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="file">The container's name (a path, or a label for one in memory).</param>
    /// <param name="objectId">The object being read, or null for the header and the directory.</param>
    /// <param name="offset">The file offset where the problem is.</param>
    /// <param name="problem">What is wrong.</param>
    /// <param name="inner">The cause, if any.</param>
    public DatContainerException(string file, uint? objectId, long offset, string problem, Exception? inner = null)
        : base(Text(file, objectId, offset, problem), inner)
    {
        File = file;
        ObjectId = objectId;
        Offset = offset;
    }

    /// <summary>Initializes a new instance.</summary>
    public DatContainerException()
    {
        File = string.Empty;
    }

    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">The message.</param>
    public DatContainerException(string message)
        : base(message)
    {
        File = string.Empty;
    }

    /// <summary>Initializes a new instance.</summary>
    /// <param name="message">The message.</param>
    /// <param name="inner">The cause.</param>
    public DatContainerException(string message, Exception inner)
        : base(message, inner)
    {
        File = string.Empty;
    }

    /// <summary>Gets the container's name.</summary>
    public string File { get; }

    /// <summary>Gets the object being read, or null for the header and the directory.</summary>
    public uint? ObjectId { get; }

    /// <summary>Gets the file offset where the problem is.</summary>
    public long Offset { get; }

    private static string Text(string file, uint? objectId, long offset, string problem) =>
        string.Create(CultureInfo.InvariantCulture, $"{file}: {(objectId is { } id ? "object " + RecordIds.Text(id) + ", " : string.Empty)}offset 0x{offset:X}: {problem}");
}
