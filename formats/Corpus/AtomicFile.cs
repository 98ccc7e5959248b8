using System.Text;

namespace AcPhys.Formats.Corpus;

/// <summary>
/// Writes files so that a killed process never leaves a half-written one: temp file in the same folder, flush to disk,
/// rename. A symlink is written through (its final target is replaced, the link stays); a character device (such as
/// <c>/dev/null</c>) is written in place; a FIFO, socket or block device is refused, never renamed over (issue 28).
/// </summary>
public static class AtomicFile
{
    /// <summary>Writes text atomically, replacing any existing file.</summary>
    /// <param name="path">Destination.</param>
    /// <param name="text">Content (UTF-8, no BOM).</param>
    public static void WriteAllText(string path, string text) => WriteAllBytes(path, new UTF8Encoding(false).GetBytes(text));

    /// <summary>Writes bytes atomically, replacing any existing file.</summary>
    /// <param name="path">Destination.</param>
    /// <param name="bytes">Content.</param>
    /// <exception cref="IOException">The path is a FIFO, socket or block device, or the write failed.</exception>
    public static void WriteAllBytes(string path, byte[] bytes)
    {
        string full = Target(path);
        switch (SpecialFile.KindOf(full))
        {
            case null:
                break;
            case "a character device":
                using (var device = new FileStream(full, FileMode.Open, FileAccess.Write, FileShare.ReadWrite))
                {
                    device.Write(bytes);
                }

                return;
            case string kind:
                throw new IOException($"{path} is {kind}; an output is a regular file, a character device such as /dev/null, or - for stdout");
        }

        string dir = Path.GetDirectoryName(full) ?? ".";
        Directory.CreateDirectory(dir);
        string temp = Path.Combine(dir, "." + Path.GetFileName(full) + "." + Environment.ProcessId + "." + Guid.NewGuid().ToString("N")[..8] + ".tmp");
        try
        {
            using (var stream = new FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None))
            {
                stream.Write(bytes);
                stream.Flush(flushToDisk: true);
            }

            File.Move(temp, full, overwrite: true);
        }
        finally
        {
            if (File.Exists(temp))
            {
                File.Delete(temp);
            }
        }
    }

    /// <summary>Returns the file a write to <paramref name="path"/> replaces: the path itself, or a symlink's final target.</summary>
    /// <param name="path">The path.</param>
    /// <returns>The full path of the file to replace.</returns>
    public static string Target(string path)
    {
        string full = Path.GetFullPath(path);
        if (new FileInfo(full).LinkTarget is null)
        {
            return full;
        }

        if (SpecialFile.KindOf(full) is not null)
        {
            return full; // /dev/stdout and the like: opened through the link, in place
        }

        try
        {
            var final = File.ResolveLinkTarget(full, returnFinalTarget: true);
            return final is null ? full : Path.GetFullPath(final.FullName);
        }
        catch (IOException)
        {
            return full; // a link loop: the write fails with the system's own message
        }
    }
}
