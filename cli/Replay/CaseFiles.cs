using AcPhys.Formats;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Dat;

namespace AcPhys.Cli.Replay;

/// <summary>Reads a case from a corpus file or from a record folder (docs/dat-scenes.md: a folder with manifest.json whose walk makes it a scene walk).</summary>
internal static class CaseFiles
{
    /// <summary>Tests whether a path names a readable input: a file or a record folder.</summary>
    /// <param name="path">The path.</param>
    /// <returns>True when it exists as either.</returns>
    public static bool Exists(string path) => File.Exists(path) || DatFolder.IsRecordFolder(path);

    /// <summary>Reads the entry.</summary>
    /// <param name="path">A corpus file or a record folder.</param>
    /// <returns>The entry.</returns>
    /// <exception cref="InputFormatException">The file is not a valid corpus entry.</exception>
    /// <exception cref="InputFormatException">The folder's records or manifest are not valid.</exception>
    /// <exception cref="UsageException">The folder holds a bare scene (no walk).</exception>
    public static CorpusEntry Read(string path) => DatFolder.IsRecordFolder(path)
        ? DatFolder.ReadEntry(path) ?? throw new UsageException($"{path}: the record folder holds a scene but no walk (its manifest has no \"walk\"); nothing to replay")
        : CorpusJson.ReadFile(path);
}
