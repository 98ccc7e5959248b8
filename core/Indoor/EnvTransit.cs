using System.Numerics;

namespace AcPhys.Core;

/// <summary>The indoor transit steps of find_cell_list: env cell portals (facts §5.1) and building entry (facts §5.3).</summary>
public static class EnvTransit
{
    /// <summary>
    /// <c>EnvCell.find_transit_cells</c>, sphere variant (facts §5.1): for each portal in dat order, an exit adds the
    /// outdoor cells when a sphere straddles its plane; a loaded neighbour is added when a sphere intersects it; an
    /// unresolvable neighbour is added as a load hint when a sphere reaches the neighbour's side (PortalSide).
    /// </summary>
    /// <param name="array">The array being built.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="cell">The env cell whose portals are tested.</param>
    /// <param name="position">The query position's cell id (its block frame is the spheres' frame).</param>
    /// <param name="spheres">Sphere centres in the position's block frame.</param>
    /// <param name="fidelity">Retail or ACE.</param>
    public static void FindTransitCells(CellArray array, IScene scene, EnvCell cell, CellId position, ReadOnlySpan<Sphere> spheres, IndoorFidelity fidelity)
    {
        bool checkOutside = false;
        var shift = fidelity.ReframeTransit ? LandDefs.GetBlockOffset(position, cell.Id) : Vector3.Zero;
        foreach (var portal in cell.Portals)
        {
            if (portal.LeadsOutside(fidelity))
            {
                // No PortalSide test and no polygon extent: the infinite plane, both bounds strict (EC:311-371).
                foreach (var s in spheres)
                {
                    float d = portal.Plane.Distance(cell.Frame.GlobalToLocal(s.Center - shift));
                    float r = s.Radius + LandDefs.Epsilon;
                    if (d > -r && d < r)
                    {
                        checkOutside = true;
                        break;
                    }
                }

                continue;
            }

            var otherId = cell.Id.WithLow(portal.OtherCellId);
            var other = fidelity.AceNeighbourViaVisibleCells && !cell.Sees(otherId) ? null : scene.GetEnvCell(otherId);
            if (other is not null)
            {
                var otherShift = fidelity.ReframeTransit ? LandDefs.GetBlockOffset(position, other.Id) : Vector3.Zero;
                foreach (var s in spheres)
                {
                    // The neighbour's own frame, radius not padded (the BSP adds its 0.01).
                    if (other.Volume.SphereIntersects(new Sphere(other.Frame.GlobalToLocal(s.Center - otherShift), s.Radius)) != BoundingType.Outside)
                    {
                        array.Add(other.Id, true);
                        break;
                    }
                }

                continue;
            }

            foreach (var s in spheres)
            {
                // Load hint: this cell's frame, R = r + EPS; PortalSide ⇒ the neighbour is on the positive side (facts §5.4).
                float d = portal.Plane.Distance(cell.Frame.GlobalToLocal(s.Center - shift));
                float r = s.Radius + LandDefs.Epsilon;
                if ((portal.PortalSide && d > -r) || (!portal.PortalSide && d < r))
                {
                    array.Add(fidelity.AceLoadHintLowKey ? new CellId(portal.OtherCellId) : otherId, false);
                    break;
                }
            }
        }

        if (checkOutside)
        {
            OutdoorCells.AddAllOutsideCells(array, position, Vector3.Zero, spheres, scene, fidelity.Outdoor);
        }
    }

    /// <summary>
    /// <c>BuildingObj.find_building_transit_cells</c> then <c>EnvCell.check_building_transit</c>, spheres (facts §5.3):
    /// for each building portal in order, the env cell behind it is added when a sphere intersects it. The sphere is
    /// used in the position's block frame with no block offset (facts §6.11), unless the fidelity re-frames.
    /// </summary>
    /// <param name="array">The array.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="landCell">The land cell the building is attached to.</param>
    /// <param name="building">The building.</param>
    /// <param name="position">The query position's cell id.</param>
    /// <param name="spheres">Sphere centres in the position's block frame.</param>
    /// <param name="fidelity">Retail or ACE.</param>
    /// <returns>True when an interior cell was hit (HitsInteriorCell).</returns>
    public static bool FindBuildingTransitCells(CellArray array, IScene scene, CellId landCell, Building building, CellId position, ReadOnlySpan<Sphere> spheres, IndoorFidelity fidelity)
    {
        bool hit = false;
        var portals = building.Portals;
        for (int i = 0; i < portals.Count; i++)
        {
            var portal = portals[i]; // by index: a foreach over the interface would box its enumerator
            var env = scene.GetEnvCell(landCell.WithLow(portal.OtherCellId));
            if (env is null || portal.OtherPortalId == BldPortal.None)
            {
                continue;
            }

            var shift = fidelity.ReframeTransit ? LandDefs.GetBlockOffset(position, env.Id) : Vector3.Zero;
            foreach (var s in spheres)
            {
                if (env.Volume.SphereIntersects(new Sphere(env.Frame.GlobalToLocal(s.Center - shift), s.Radius)) != BoundingType.Outside)
                {
                    hit = true;
                    array.Add(env.Id, true);
                    break; // retail stops at the first hit (same membership as ACE)
                }
            }
        }

        return hit;
    }
}
