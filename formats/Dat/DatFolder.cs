using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;

namespace AcPhys.Formats.Dat;

/// <summary>
/// A record folder: <c>XXXXXXXX.bin</c> per record (the raw record bytes, as a dat reader assembles them) and
/// <c>manifest.json</c>. Written into a temp folder beside the target and renamed, so a killed run leaves nothing half-written.
/// </summary>
public static class DatFolder
{
    /// <summary>The manifest's file name.</summary>
    public const string ManifestName = "manifest.json";

    private const long MaxRecordBytes = 64L << 20;

    /// <summary>Tests whether a path is a record folder (a directory holding manifest.json).</summary>
    /// <param name="path">The path.</param>
    /// <returns>True for a record folder.</returns>
    public static bool IsRecordFolder(string path) => Directory.Exists(path) && File.Exists(Path.Combine(path, ManifestName));

    /// <summary>Writes an export. An existing target must be empty or a record folder (it is replaced).</summary>
    /// <param name="dir">The target folder.</param>
    /// <param name="export">The records and manifest.</param>
    /// <exception cref="IOException">The target is a non-empty folder that is not a record folder, or a file.</exception>
    public static void Write(string dir, DatExport export)
    {
        string full = Path.GetFullPath(dir.TrimEnd(Path.DirectorySeparatorChar));
        string parent = Path.GetDirectoryName(full) ?? ".";
        if (File.Exists(full) || (Directory.Exists(full) && !IsRecordFolder(full) && Directory.EnumerateFileSystemEntries(full).Any()))
        {
            throw new IOException($"{dir}: exists and is not an empty folder or a record folder; refusing to replace it");
        }

        Directory.CreateDirectory(parent);
        string stamp = Environment.ProcessId + "." + Guid.NewGuid().ToString("N")[..8];
        string temp = Path.Combine(parent, "." + Path.GetFileName(full) + "." + stamp + ".tmp");
        string old = Path.Combine(parent, "." + Path.GetFileName(full) + "." + stamp + ".old");
        try
        {
            Directory.CreateDirectory(temp);
            foreach (var (record, bytes) in export.Records)
            {
                AtomicFile.WriteAllBytes(Path.Combine(temp, record.File), bytes);
            }

            AtomicFile.WriteAllText(Path.Combine(temp, ManifestName), DatManifestJson.Write(export.Manifest));
            if (Directory.Exists(full))
            {
                Directory.Move(full, old);
            }

            Directory.Move(temp, full);
        }
        finally
        {
            foreach (string d in new[] { temp, old })
            {
                if (Directory.Exists(d))
                {
                    Directory.Delete(d, recursive: true);
                }
            }
        }
    }

    /// <summary>Reads a record folder.</summary>
    /// <param name="dir">The folder.</param>
    /// <returns>The manifest and the scene.</returns>
    /// <exception cref="InputFormatException">Any defect: unreadable or missing files, unlisted records, bad records.</exception>
    public static (DatManifest Manifest, Scene Scene) Read(string dir)
    {
        string manifestPath = Path.Combine(dir, ManifestName);
        var manifest = DatManifestJson.Read(ReadText(manifestPath), manifestPath);
        var listed = manifest.Records.Select(r => r.File).ToHashSet(StringComparer.Ordinal);
        foreach (string file in Directory.EnumerateFiles(dir, "*.bin"))
        {
            if (!listed.Contains(Path.GetFileName(file)))
            {
                throw new InputFormatException($"{file}: a record file the manifest does not list");
            }
        }

        var scene = DatSceneReader.Read(manifest, r => ReadBytes(Path.Combine(dir, r.File)));
        return (manifest, scene);
    }

    /// <summary>Reads a record folder as a corpus entry: a scene walk when the manifest carries one.</summary>
    /// <param name="dir">The folder.</param>
    /// <returns>The entry, or null for a bare scene (no walk).</returns>
    /// <exception cref="InputFormatException">Any defect.</exception>
    public static CorpusEntry? ReadEntry(string dir)
    {
        var (manifest, scene) = Read(dir);
        return manifest is { Header: { } h, Walk: { } walk } ? h with { SceneWalk = new SceneWalk(scene, walk) } : null;
    }

    /// <summary>Builds the export of a corpus entry (kind scene-walk): the scene's records and a manifest carrying the rest.</summary>
    /// <param name="entry">The entry.</param>
    /// <param name="source">Its file name.</param>
    /// <returns>The export.</returns>
    public static DatExport Export(CorpusEntry entry, string source)
    {
        var sw = entry.SceneWalk ?? throw new ArgumentException("the entry is not a scene walk", nameof(entry));
        var export = DatSceneWriter.Write(sw.Scene, entry.Title, source);
        var header = entry with { SceneWalk = null };
        return export with { Manifest = export.Manifest with { Header = header, Walk = sw.Walk } };
    }

    private static string ReadText(string path)
    {
        try
        {
            return File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new InputFormatException($"{path}: cannot read: {e.Message}");
        }
    }

    private static byte[] ReadBytes(string path)
    {
        try
        {
            var info = new FileInfo(path);
            if (!info.Exists)
            {
                throw new InputFormatException($"{path}: listed in the manifest but missing");
            }

            if (info.Length > MaxRecordBytes)
            {
                throw new InputFormatException($"{path}: {info.Length} bytes; a record is at most {MaxRecordBytes}");
            }

            return File.ReadAllBytes(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new InputFormatException($"{path}: cannot read: {e.Message}");
        }
    }
}
