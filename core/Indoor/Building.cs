using System.Numerics;

namespace AcPhys.Core;

/// <summary>One building portal (facts §5.4, CBldPortal): the env cell behind it (same block) and that cell's portal index.</summary>
/// <param name="Flags">Dat flags (PortalSide as for cell portals; unused by the sphere path).</param>
/// <param name="OtherCellId">Low word of the env cell, in the owning land cell's block.</param>
/// <param name="OtherPortalId">Index into that cell's portal list; 0xFFFF = none (the entry test is skipped).</param>
public readonly record struct BldPortal(ushort Flags, ushort OtherCellId, ushort OtherPortalId)
{
    /// <summary>The OtherPortalId meaning "no portal".</summary>
    public const ushort None = 0xFFFF;
}

/// <summary>A building: its frame origin in its declared block's frame and its portals into env cells (facts §5.3).</summary>
/// <param name="Block">The landblock the building is declared in.</param>
/// <param name="Origin">The frame origin, in <paramref name="Block"/>'s frame.</param>
/// <param name="Portals">Building portals in dat order.</param>
public sealed record Building(LandblockId Block, Vector3 Origin, IReadOnlyList<BldPortal> Portals)
{
    /// <summary>
    /// Returns the land cell that owns the building: the origin AdjustToOutside'd against the block id, or
    /// <see cref="CellId.None"/> when it falls in another block (discarded, as LB:433-456 and retail do).
    /// </summary>
    /// <returns>The owning land cell, or none.</returns>
    public CellId OwningCell()
    {
        var id = Block.BlockCell;
        var origin = Origin;
        if (!LandDefs.AdjustToOutside(ref id, ref origin) || id.Landblock != Block)
        {
            return CellId.None;
        }

        return id;
    }
}
