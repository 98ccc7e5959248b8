using AcPhys.Formats.Corpus;

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

        string target = AtomicFile.Target(path); // a symlink is written through: check its target
        if (SpecialFile.KindOf(target) is string kind)
        {
            if (kind == "a character device")
            {
                return; // written in place (/dev/null); a full device fails at the write, exit 3
            }

            throw new OutputPathException($"cannot write '{path}' ({option}): it is {kind}; an output is a regular file, a character device such as /dev/null, or - for stdout");
        }

        if (Directory.Exists(target))
        {
            throw new OutputPathException($"cannot write '{path}' ({option}): it links to a directory");
        }

        string folder = Path.GetDirectoryName(target) ?? ".";
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

    /// <summary>Fails at once when <paramref name="path"/> cannot be an output folder: empty, a file, or a folder that cannot be created or written.</summary>
    /// <param name="option">The option (or variable) that named it, for the message.</param>
    /// <param name="path">The folder.</param>
    /// <exception cref="OutputPathException">It cannot be written.</exception>
    public static void CheckFolder(string option, string path)
    {
        if (path.Length == 0)
        {
            throw new OutputPathException($"{option}: empty path (give a folder)");
        }

        if (File.Exists(path) || SpecialFile.KindOf(path) is not null)
        {
            throw new OutputPathException($"cannot write into '{path}' ({option}): it is a file, not a folder");
        }

        string probe = Path.Combine(path, $".acphys.{Environment.ProcessId}.probe");
        try
        {
            Directory.CreateDirectory(path);
            using (File.Create(probe, 1, FileOptions.DeleteOnClose))
            {
            }
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException or NotSupportedException or ArgumentException)
        {
            throw new OutputPathException($"cannot write into '{path}' ({option}): {e.Message}", e);
        }
    }

    /// <summary>Fails when two outputs name one file, or an output is (or lies inside) an input: a usage error before any work (issue 28).</summary>
    /// <param name="outputs">The outputs given, with their options (null paths and <c>-</c> are skipped).</param>
    /// <param name="inputs">The input files and folders.</param>
    /// <exception cref="OutputPathException">Two paths collide.</exception>
    public static void CheckDistinct(IEnumerable<(string Option, string? Path)> outputs, IEnumerable<string> inputs)
    {
        var given = outputs.Where(o => o.Path is { Length: > 0 } p && p != Stdout).Select(o => (o.Option, o.Path, Full: Same(o.Path!))).ToArray();
        for (int i = 0; i < given.Length; i++)
        {
            for (int j = i + 1; j < given.Length; j++)
            {
                if (given[i].Full == given[j].Full)
                {
                    throw new OutputPathException($"{given[i].Option} and {given[j].Option} name the same file '{given[i].Path}'; give each output its own path");
                }
            }
        }

        foreach (string input in inputs.Where(p => p.Length > 0))
        {
            string full = Same(input);
            foreach (var o in given)
            {
                if (o.Full == full || o.Full.StartsWith(full.TrimEnd(Path.DirectorySeparatorChar) + Path.DirectorySeparatorChar, StringComparison.Ordinal))
                {
                    throw new OutputPathException($"{o.Option} '{o.Path}' would overwrite the input '{input}'; write the output elsewhere");
                }
            }
        }
    }

    // One spelling per file: full path, symlinks of the last component followed.
    private static string Same(string path) => AtomicFile.Target(path).TrimEnd(Path.DirectorySeparatorChar);

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
