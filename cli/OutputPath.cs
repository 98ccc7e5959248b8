using AcPhys.Spec.Corpus;

namespace AcPhys.Cli;

/// <summary>
/// Output files named on the command line (<c>-o</c>, <c>--junit</c>, <c>--markdown</c>, <c>--json</c>): checked before
/// the work starts, written atomically, and <c>-</c> means stdout.
/// </summary>
internal static class OutputPath
{
    /// <summary>The path that means standard output.</summary>
    public const string Stdout = "-";

    /// <summary>Fails at once when <paramref name="path"/> cannot be written: empty, a directory, or a folder that is missing or read-only.</summary>
    /// <param name="option">The option that named it, for the message.</param>
    /// <param name="path">The path, or null when the option was not given.</param>
    /// <exception cref="OutputPathException">It cannot be written.</exception>
    public static void Check(string option, string? path)
    {
        if (path is null || path == Stdout)
        {
            return;
        }

        if (path.Length == 0)
        {
            throw new OutputPathException($"{option}: empty path (give a file, or - for stdout)");
        }

        if (Directory.Exists(path))
        {
            throw new OutputPathException($"cannot write '{path}' ({option}): it is a directory");
        }

        string folder = Path.GetDirectoryName(Path.GetFullPath(path)) ?? ".";
        if (!Directory.Exists(folder))
        {
            throw new OutputPathException($"cannot write '{path}' ({option}): no folder '{folder}'");
        }

        // The only honest test of "writable" is writing: a probe file beside the target, removed at once.
        string probe = Path.Combine(folder, $".{Path.GetFileName(path)}.{Environment.ProcessId}.probe");
        try
        {
            using (File.Create(probe, 1, FileOptions.DeleteOnClose))
            {
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new OutputPathException($"cannot write '{path}' ({option}): {e.Message}", e);
        }
    }

    /// <summary>Writes <paramref name="text"/> to <paramref name="path"/> atomically, or to stdout for <c>-</c>.</summary>
    /// <param name="path">The path, or <c>-</c>.</param>
    /// <param name="text">The contents.</param>
    /// <exception cref="OutputPathException">The file could not be written.</exception>
    public static void Write(string path, string text)
    {
        if (path == Stdout)
        {
            Console.Out.Write(text);
            Console.Out.Flush();
            return;
        }

        try
        {
            AtomicFile.WriteAllText(path, text);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new OutputPathException($"cannot write '{path}': {e.Message}", e);
        }
    }
}

/// <summary>An output path that cannot be written (exit <see cref="ExitCodes.OutputError"/>).</summary>
internal sealed class OutputPathException : UsageException
{
    /// <summary>Initializes a new instance of the <see cref="OutputPathException"/> class.</summary>
    public OutputPathException()
    {
    }

    /// <summary>Initializes a new instance of the <see cref="OutputPathException"/> class.</summary>
    /// <param name="message">The message.</param>
    public OutputPathException(string message)
        : base(message)
    {
    }

    /// <summary>Initializes a new instance of the <see cref="OutputPathException"/> class.</summary>
    /// <param name="message">The message.</param>
    /// <param name="inner">The cause.</param>
    public OutputPathException(string message, Exception inner)
        : base(message, inner)
    {
    }
}
