namespace AcPhys.Core;

/// <summary>
/// An indoor cell (facts §5): id, frame in its landblock's frame, geometry, portals in dat order, and the cells
/// visible from it. Immutable after construction.
/// </summary>
public sealed class EnvCell
{
    private readonly CellPortal[] portals;
    private readonly CellId[] visible;

    /// <summary>Initializes a new instance.</summary>
    /// <param name="id">An env cell id (low word 0x100..0xFFFD).</param>
    /// <param name="frame">Frame in the cell's block frame (unit rotation).</param>
    /// <param name="volume">The geometry, in the cell's local frame.</param>
    /// <param name="portals">Portals in dat order.</param>
    /// <param name="visibleCells">Full ids of the cells visible from this one (the VisibleCells list).</param>
    public EnvCell(CellId id, Frame frame, ICellVolume volume, IReadOnlyList<CellPortal> portals, IReadOnlyList<CellId> visibleCells)
    {
        if (!id.IsEnv)
        {
            throw new ArgumentException($"{id} is not an env cell id", nameof(id));
        }

        Id = id;
        Frame = frame;
        Volume = volume;
        this.portals = [.. portals];
        visible = [.. visibleCells];
    }

    /// <summary>Gets the cell id.</summary>
    public CellId Id { get; }

    /// <summary>Gets the frame (origin and rotation in the block frame).</summary>
    public Frame Frame { get; }

    /// <summary>Gets the geometry.</summary>
    public ICellVolume Volume { get; }

    /// <summary>Gets the portals, in dat order.</summary>
    public ReadOnlySpan<CellPortal> Portals => portals;

    /// <summary>Tests whether a cell is in this cell's VisibleCells.</summary>
    /// <param name="id">A full id.</param>
    /// <returns>True when listed.</returns>
    public bool Sees(CellId id) => Array.IndexOf(visible, id) >= 0;

    /// <summary><c>point_in_cell</c> (facts §5.5): the block-frame point mapped into the cell and tested.</summary>
    /// <param name="p">A point in this cell's block frame.</param>
    /// <param name="fidelity">Retail answers false for a cell without portals; ACE does not (facts §7 #13).</param>
    /// <returns>True when inside.</returns>
    public bool PointInCell(System.Numerics.Vector3 p, IndoorFidelity fidelity) =>
        (portals.Length > 0 || fidelity.AceNoPortalGuard) && Volume.PointInside(Frame.GlobalToLocal(p));
}
