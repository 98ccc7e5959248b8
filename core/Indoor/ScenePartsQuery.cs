namespace AcPhys.Core;

/// <summary>
/// The parts / bounding-box cell list over a scene (<c>find_bbox_cell_list</c>, facts §3.5, §5.2, §5.3): the cell
/// list of an object given by its parts instead of spheres. Reset, seed from the anchor (the first part), transit
/// closure breadth-first in insertion order with the parts variants, and the indoor visibility filter for static
/// placement. There is no containing-cell pick (the parts list has no sphere 0).
/// </summary>
/// <remarks>
/// The closure mirrors find_cell_list (facts §4 step 4a) with the parts transit: an env cell runs
/// <see cref="EnvTransitParts.FindTransitCells"/> (§5.2); a land cell runs the parts add_all_outside_cells (a no-op once
/// latched, §3.5) and then, per building portal, <see cref="EnvTransitParts.CheckBuildingTransit"/> (§5.3: retail's box-side
/// pairing, or ACE's under <see cref="IndoorFidelity.AceBoxSidePairing"/>, §7 #14). The visibility filter is the sphere variant's (§4 step 5).
/// </remarks>
public static class ScenePartsQuery
{
    /// <summary>Runs the parts cell list.</summary>
    /// <param name="array">Reused output array.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="parts">The parts; the first is the anchor, whose cell is the position (land or env).</param>
    /// <param name="loadCells">True for a transition (no visibility filter), false for static placement.</param>
    /// <param name="fidelity">Retail or ACE on the documented indoor differences.</param>
    /// <param name="partsFidelity">Retail or ACE for the outdoor parts variant (facts §7 #3–#4).</param>
    /// <returns>True when an interior cell was hit (an indoor anchor or a building entry): the path's HitsInteriorCell.</returns>
    public static bool FindCellList(CellArray array, IScene scene, ReadOnlySpan<Part> parts, bool loadCells, IndoorFidelity fidelity, PartsFidelity partsFidelity = default)
    {
        if (fidelity.AceKeepsStaleCells)
        {
            array.AddedOutside = false; // ACE: NumCells = 0 but the dictionary keeps earlier entries (facts §7 #6)
        }
        else
        {
            array.Reset();
        }

        if (parts.IsEmpty)
        {
            return false;
        }

        var position = parts[0].Cell;
        bool hits = false;
        bool indoor = position.IsIndoorByLowWord;
        bool visible;
        if (indoor)
        {
            visible = scene.GetEnvCell(position) is not null;
            hits = true;
            array.Add(position, visible);
        }
        else
        {
            visible = !position.IsNone && position.IsLand && scene.IsLoaded(position.Landblock);
            OutdoorParts.AddAllOutsideCells(array, parts, position, scene, partsFidelity);
        }

        if (visible)
        {
            for (int i = 0; i < array.Count; i++)
            {
                var entry = array[i];
                if (!entry.Loaded)
                {
                    continue;
                }

                if (entry.Id.IsEnv)
                {
                    if (scene.GetEnvCell(entry.Id) is { } env)
                    {
                        EnvTransitParts.FindTransitCells(array, scene, env, parts, fidelity, partsFidelity);
                    }
                }
                else if (entry.Id.IsLand)
                {
                    // LandCell.find_transit_cells, parts: add_all_outside_cells (latched), then its building's portals.
                    OutdoorParts.AddAllOutsideCells(array, parts, entry.Id, scene, partsFidelity);
                    if (scene.GetBuilding(entry.Id) is { } building)
                    {
                        hits |= EnterBuilding(array, scene, entry.Id, building, parts, fidelity, partsFidelity);
                    }
                }
            }
        }

        bool filterGuard = fidelity.AceFilterOutsideGuard || visible;
        if (!(loadCells && !fidelity.AceTransitionFilters) && indoor && filterGuard)
        {
            SceneQuery.FilterVisible(array, scene, position);
        }

        return hits;
    }

    // BuildingObj.find_building_transit_cells, parts: each building portal's env cell (same block) checks the parts.
    private static bool EnterBuilding(CellArray array, IScene scene, CellId landCell, Building building, ReadOnlySpan<Part> parts, IndoorFidelity fidelity, PartsFidelity partsFidelity)
    {
        bool hit = false;
        var portals = building.Portals;
        for (int i = 0; i < portals.Count; i++)
        {
            var portal = portals[i];
            if (scene.GetEnvCell(landCell.WithLow(portal.OtherCellId)) is { } env)
            {
                hit |= EnvTransitParts.CheckBuildingTransit(array, scene, env, portal.OtherPortalId, parts, fidelity, partsFidelity);
            }
        }

        return hit;
    }
}
