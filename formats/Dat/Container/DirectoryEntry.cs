namespace AcPhys.Formats.Dat.Container;

/// <summary>One entry of a directory node (dat-container.md "Directory"): 6 × u32.</summary>
/// <param name="Flags">Flags (unused by ACE).</param>
/// <param name="Id">The object id.</param>
/// <param name="Offset">The file offset of the object's first block.</param>
/// <param name="Size">The object's size in bytes (its chain's payload).</param>
/// <param name="Date">Date.</param>
/// <param name="Iteration">Iteration.</param>
public readonly record struct DirectoryEntry(uint Flags, uint Id, uint Offset, uint Size, uint Date, uint Iteration)
{
    /// <summary>The entry's length in a node.</summary>
    public const int Length = 24;
}
