using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;

namespace AcPhys.Formats.Dat;

/// <summary>One record of a folder: its id, which dat it belongs to, and its type (the file is <see cref="RecordIds.FileName"/>).</summary>
/// <param name="Id">The record id.</param>
/// <param name="PortalDat">True for the portal dat (Environment), false for the cell dat.</param>
/// <param name="Type">The record type.</param>
public sealed record ManifestRecord(uint Id, bool PortalDat, RecordType Type)
{
    /// <summary>Gets the file name.</summary>
    public string File => RecordIds.FileName(Id);
}

/// <summary>
/// A record folder's manifest.json (docs/dat-scenes.md, "Manifest"): the records, and what a scene has that records
/// cannot carry — loaded and unloaded blocks, unloaded cells, visible cells in other blocks — plus the title, the
/// source and, for a scene-walk corpus file, the rest of the entry (header fields and the walk).
/// </summary>
/// <param name="Title">The scene's title.</param>
/// <param name="Source">Where the scene came from (a file name).</param>
/// <param name="Records">The records, in reading order (cells and buildings come back in this order).</param>
/// <param name="Blocks">Loaded blocks.</param>
/// <param name="UnloadedBlocks">Declared but unloaded blocks.</param>
/// <param name="UnloadedCells">Unloaded env cells.</param>
/// <param name="VisibleElsewhere">Per cell, the visible cells in other blocks (an EnvCell lists low words of its own block only).</param>
public sealed record DatManifest(
    string Title,
    string Source,
    IReadOnlyList<ManifestRecord> Records,
    IReadOnlyList<LandblockId> Blocks,
    IReadOnlyList<LandblockId> UnloadedBlocks,
    IReadOnlyList<CellId> UnloadedCells,
    IReadOnlyList<(CellId Cell, IReadOnlyList<CellId> Visible)> VisibleElsewhere)
{
    /// <summary>The value of the <c>format</c> field.</summary>
    public const string FormatName = "acphys-dat-scene";

    /// <summary>The current version.</summary>
    public const int CurrentVersion = 1;

    /// <summary>Gets the corpus entry's header (title, invariant, foundBy, seed, catches; no case), or null for a bare scene.</summary>
    public CorpusEntry? Header { get; init; }

    /// <summary>Gets the walk of a scene-walk entry, or null.</summary>
    public Walk? Walk { get; init; }
}
