namespace AcPhys.Core;

/// <summary>
/// One portal of an env cell (facts §5.4, DL/CellPortal.cs): dat flags, the portal polygon's id and plane (cell-local),
/// the cell behind it (low word; 0xFFFF = outside) and that cell's portal index.
/// </summary>
/// <param name="Flags">Dat flags: 1 ExactMatch, 2 clear ⇒ PortalSide, 4 ⇒ the other side is outside (retail).</param>
/// <param name="PolygonId">The portal polygon's key in the cell structure.</param>
/// <param name="OtherCellId">Low word of the cell behind; 0xFFFF = outside.</param>
/// <param name="OtherPortalId">Index into the other cell's portal list; 0xFFFF = none.</param>
/// <param name="Plane">The portal polygon's plane in the owning cell's local frame.</param>
public readonly record struct CellPortal(ushort Flags, ushort PolygonId, ushort OtherCellId, ushort OtherPortalId, CellPlane Plane)
{
    /// <summary>The OtherCellId of an exit to the outside.</summary>
    public const ushort Outside = 0xFFFF;

    /// <summary>The flag bit whose absence means PortalSide.</summary>
    public const ushort NegativeSideFlag = 2;

    /// <summary>The flag bit retail reads as "the other side is outside" (facts §5.4, §7 #12).</summary>
    public const ushort OutsideFlag = 4;

    /// <summary>
    /// Gets a value indicating whether the owning cell lies on the plane's negative side and the cell behind on the positive
    /// side: PortalSide = (Flags &amp; 2) == 0 (facts §5.4; the seed's "intuition" paragraph has this backwards).
    /// </summary>
    public bool PortalSide => (Flags & NegativeSideFlag) == 0;

    /// <summary>Returns the dat flags for a portal side and an exit.</summary>
    /// <param name="portalSide">True when the owning cell is on the negative side.</param>
    /// <param name="outside">True for an exit to the outside.</param>
    /// <returns>The flags.</returns>
    public static ushort FlagsFor(bool portalSide, bool outside) => (ushort)((portalSide ? 0 : NegativeSideFlag) | (outside ? OutsideFlag : 0));

    /// <summary>Tests whether this portal leads outside under a fidelity.</summary>
    /// <param name="fidelity">Retail reads flag 4, ACE tests OtherCellId == 0xFFFF (facts §7 #12).</param>
    /// <returns>True for an exit.</returns>
    public bool LeadsOutside(IndoorFidelity fidelity) => fidelity.AceOutsideByCellId ? OtherCellId == Outside : (Flags & OutsideFlag) != 0;
}
