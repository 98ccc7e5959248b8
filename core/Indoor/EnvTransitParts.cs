namespace AcPhys.Core;

/// <summary>The parts / bounding-box variants of the indoor transit steps (facts §5.2, §5.3).</summary>
public static class EnvTransitParts
{
    /// <summary>
    /// <c>EnvCell.find_transit_cells</c>, parts (facts §5.2): per portal, per part, a sphere test against the portal plane
    /// gated by PortalSide, then the part's box against the plane; an exit sets checkOutside, an unresolvable neighbour
    /// is a load hint, a neighbour whose BSP the box intersects is added. Afterwards the parts variant of
    /// add_all_outside_cells, called for this cell.
    /// </summary>
    /// <param name="array">The array.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="cell">The env cell.</param>
    /// <param name="parts">The parts (each with its own cell and frame; the part's origin is its sphere's centre).</param>
    /// <param name="fidelity">Retail or ACE (exit detection, neighbour lookup, load-hint key).</param>
    /// <param name="partsFidelity">Retail or ACE for the outdoor parts variant.</param>
    public static void FindTransitCells(CellArray array, IScene scene, EnvCell cell, ReadOnlySpan<Part> parts, IndoorFidelity fidelity, PartsFidelity partsFidelity = default)
    {
        bool checkOutside = false;
        foreach (var portal in cell.Portals)
        {
            foreach (var part in parts)
            {
                // LocalToLocal: the part's sphere centre into this cell's frame, block offset applied (POS:64-70).
                var c = cell.Frame.GlobalToLocal(part.Frame.Origin + LandDefs.GetBlockOffset(cell.Id, part.Cell));
                float r = part.Radius + LandDefs.Epsilon, d = portal.Plane.Distance(c);
                if (portal.PortalSide ? d < -r : d > r)
                {
                    continue;
                }

                var side = BoxSide.Of(portal.Plane, BoxSide.InFrame(part, cell.Id, cell.Frame));
                if ((side == Sidedness.Positive && !portal.PortalSide) || (side == Sidedness.Negative && portal.PortalSide))
                {
                    continue;
                }

                if (portal.LeadsOutside(fidelity))
                {
                    checkOutside = true;
                    break;
                }

                var otherId = cell.Id.WithLow(portal.OtherCellId);
                var other = fidelity.AceNeighbourViaVisibleCells && !cell.Sees(otherId) ? null : scene.GetEnvCell(otherId);
                if (other is null)
                {
                    array.Add(fidelity.AceLoadHintLowKey ? new CellId(portal.OtherCellId) : otherId, false);
                    break;
                }

                if (other.Volume.BoxIntersects(BoxSide.InFrame(part, other.Id, other.Frame)))
                {
                    array.Add(other.Id, true);
                    break;
                }
            }
        }

        if (checkOutside)
        {
            OutdoorParts.AddAllOutsideCells(array, parts, cell.Id, scene, partsFidelity);
        }
    }

    /// <summary>
    /// <c>EnvCell.check_building_transit</c>, parts (facts §5.3): the entering mirror of the sphere gate, then the box
    /// side — retail accepts Crossing or the side equal to portal_side (Negative when PortalSide), ACE the opposite
    /// pairing (§7 #14) — then box_intersects_cell; on acceptance the cell is added and its own parts transit runs.
    /// </summary>
    /// <param name="array">The array.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="cell">The env cell behind the building portal.</param>
    /// <param name="portalId">The building portal's OtherPortalId (an index into the cell's portals; 0xFFFF = none).</param>
    /// <param name="parts">The parts.</param>
    /// <param name="fidelity">Retail or ACE (<see cref="IndoorFidelity.AceBoxSidePairing"/>: ACE's box-side pairing, facts §7 #14).</param>
    /// <param name="partsFidelity">Retail or ACE for the outdoor parts variant the entered cell's own transit may run (facts §7 #3–#4).</param>
    /// <returns>True when the cell was entered.</returns>
    public static bool CheckBuildingTransit(CellArray array, IScene scene, EnvCell cell, ushort portalId, ReadOnlySpan<Part> parts, IndoorFidelity fidelity, PartsFidelity partsFidelity = default)
    {
        if (portalId == BldPortal.None || portalId >= cell.Portals.Length)
        {
            return false;
        }

        var portal = cell.Portals[portalId];
        foreach (var part in parts)
        {
            var c = cell.Frame.GlobalToLocal(part.Frame.Origin + LandDefs.GetBlockOffset(cell.Id, part.Cell));
            float r = part.Radius + LandDefs.Epsilon, d = portal.Plane.Distance(c);
            if (portal.PortalSide ? d > r : d < -r)
            {
                continue;
            }

            var box = BoxSide.InFrame(part, cell.Id, cell.Frame);
            var side = BoxSide.Of(portal.Plane, box);
            var inside = portal.PortalSide ? Sidedness.Negative : Sidedness.Positive;
            var accepted = fidelity.AceBoxSidePairing ? (portal.PortalSide ? Sidedness.Positive : Sidedness.Negative) : inside;
            if ((side == Sidedness.Crossing || side == accepted) && cell.Volume.BoxIntersects(box))
            {
                array.Add(cell.Id, true);
                // The entered room's exit runs add_all_outside_cells with the declared outdoor parts rules. Inside
                // find_bbox_cell_list it is a no-op (the land cell latched AddedOutside before its building, §3.5);
                // on an unlatched array it is not.
                FindTransitCells(array, scene, cell, parts, fidelity, partsFidelity);
                return true;
            }
        }

        return false;
    }
}
