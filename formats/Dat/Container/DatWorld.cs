namespace AcPhys.Formats.Dat.Container;

/// <summary>A world on disk: a cell database (landblocks, LandblockInfo, env cells) and a portal database (Environments), opened read-only.</summary>
public sealed class DatWorld : IDisposable
{
    /// <summary>Initializes a new instance (takes ownership of both).</summary>
    /// <param name="cell">The cell database.</param>
    /// <param name="portal">The portal database.</param>
    public DatWorld(DatContainer cell, DatContainer portal)
    {
        Cell = cell;
        Portal = portal;
    }

    /// <summary>Gets the cell database (client_cell_1.dat).</summary>
    public DatContainer Cell { get; }

    /// <summary>Gets the portal database (client_portal.dat).</summary>
    public DatContainer Portal { get; }

    /// <summary>Opens both files read-only (header and directory of each).</summary>
    /// <param name="cellPath">The cell database.</param>
    /// <param name="portalPath">The portal database.</param>
    /// <returns>The world.</returns>
    /// <exception cref="DatContainerException">Either file is not a readable container.</exception>
    /// <exception cref="IOException">Either file cannot be opened.</exception>
    public static DatWorld Open(string cellPath, string portalPath)
    {
        var cell = DatContainer.Open(cellPath);
        try
        {
            return new DatWorld(cell, DatContainer.Open(portalPath));
        }
        catch
        {
            cell.Dispose();
            throw;
        }
    }

    /// <summary>Gets the landblocks the cell database holds a Landblock record for, in ascending order.</summary>
    /// <returns>The blocks.</returns>
    public IEnumerable<Core.LandblockId> Landblocks() =>
        Cell.Ids.Where(id => (id & 0xFFFF) == 0xFFFF).Select(id => new Core.LandblockId((ushort)(id >> 16)));

    /// <inheritdoc/>
    public void Dispose()
    {
        Cell.Dispose();
        Portal.Dispose();
    }
}
