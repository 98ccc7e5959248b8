using System.Text;

namespace AcPhys.Spec.Corpus;

/// <summary>Writes files so that a killed process never leaves a half-written one: temp file in the same folder, flush to disk, rename.</summary>
public static class AtomicFile
{
    /// <summary>Writes text atomically, replacing any existing file.</summary>
    /// <param name="path">Destination.</param>
    /// <param name="text">Content (UTF-8, no BOM).</param>
    public static void WriteAllText(string path, string text) => WriteAllBytes(path, new UTF8Encoding(false).GetBytes(text));

    /// <summary>Writes bytes atomically, replacing any existing file.</summary>
    /// <param name="path">Destination.</param>
    /// <param name="bytes">Content.</param>
    public static void WriteAllBytes(string path, byte[] bytes)
    {
        string full = Path.GetFullPath(path);
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
}
