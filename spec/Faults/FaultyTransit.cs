using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// Env-cell portal transit (facts §5.1) and building entry (facts §5.3) as a port would write them, with at most one
/// named defect; retail fidelity only (no re-framing, neighbours among all loaded cells, exits by flag 4).
/// </summary>
internal static class FaultyTransit
{
    /// <summary><c>EnvCell.find_transit_cells</c>, spheres.</summary>
    /// <param name="array">The array being built.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="cell">The walked cell.</param>
    /// <param name="position">The query position.</param>
    /// <param name="spheres">Centres in the position's block frame.</param>
    /// <param name="defect">The defect.</param>
    public static void FindTransitCells(CellArray array, IScene scene, EnvCell cell, CellId position, ReadOnlySpan<Sphere> spheres, IndoorDefect defect)
    {
        var tested = defect == IndoorDefect.TransitSphere0Only ? spheres[..1] : spheres;
        bool checkOutside = false;
        foreach (var portal in cell.Portals)
        {
            if (portal.LeadsOutside(default))
            {
                checkOutside |= Straddles(cell, portal, tested, defect == IndoorDefect.ExitStraddleOneSided, defect);
                continue;
            }

            var otherId = cell.Id.WithLow(portal.OtherCellId);
            var other = scene.GetEnvCell(otherId);
            if (other is not null && defect == IndoorDefect.NeighbourByPlane)
            {
                // The load-hint side test reused for a loaded neighbour: its volume is never asked (facts §5.1).
                if (ReachesSide(cell, portal, tested, defect))
                {
                    array.Add(other.Id, true);
                }

                continue;
            }

            if (other is not null && defect == IndoorDefect.PortalGuardInTransit && other.Portals.Length == 0)
            {
                continue; // the defect: "a cell nobody can leave is no candidate" (retail only refuses it in point_in_cell, facts §5.5)
            }

            if (other is not null)
            {
                var frame = defect == IndoorDefect.NeighbourWrongFrame ? cell.Frame : other.Frame; // facts §5.1: the neighbour's own frame
                foreach (var s in tested)
                {
                    if (other.Volume.SphereIntersects(new Sphere(frame.GlobalToLocal(s.Center), CornerFaults.NeighbourRadius(s.Radius, defect))) != BoundingType.Outside)
                    {
                        array.Add(other.Id, true);
                        break;
                    }
                }

                continue;
            }

            bool hint = defect == IndoorDefect.HintStraddleOnly ? Straddles(cell, portal, tested, false, defect) : ReachesSide(cell, portal, tested, defect);
            if (hint)
            {
                array.Add(otherId, false);
            }
        }

        if (checkOutside)
        {
            OutdoorCells.AddAllOutsideCells(array, position, System.Numerics.Vector3.Zero, spheres, scene);
        }
    }

    /// <summary><c>find_building_transit_cells</c> then <c>check_building_transit</c>, spheres.</summary>
    /// <param name="array">The array.</param>
    /// <param name="scene">The scene.</param>
    /// <param name="landCell">The owning land cell.</param>
    /// <param name="building">The building.</param>
    /// <param name="spheres">Centres in the position's block frame (no block offset, facts §6.11).</param>
    /// <param name="defect">The defect.</param>
    /// <returns>HitsInteriorCell as this code sets it.</returns>
    public static bool FindBuildingTransitCells(CellArray array, IScene scene, CellId landCell, Building building, ReadOnlySpan<Sphere> spheres, IndoorDefect defect)
    {
        var tested = defect == IndoorDefect.TransitSphere0Only ? spheres[..1] : spheres;
        bool hit = false;
        foreach (var portal in building.Portals)
        {
            var env = scene.GetEnvCell(landCell.WithLow(portal.OtherCellId));
            if (env is null || (portal.OtherPortalId == BldPortal.None && defect != IndoorDefect.InvalidBldPortalEntered)
                || (defect == IndoorDefect.PortalGuardInTransit && env.Portals.Length == 0))
            {
                continue; // facts §5.3: 0xFFFF marks no portal, the entry test is skipped
            }

            bool entered = false;
            foreach (var s in tested)
            {
                if (env.Volume.SphereIntersects(new Sphere(env.Frame.GlobalToLocal(s.Center), CornerFaults.BuildingRadius(s.Radius, defect))) != BoundingType.Outside)
                {
                    entered = true;
                    array.Add(env.Id, true);
                    break;
                }
            }

            hit |= entered && defect != IndoorDefect.HitsInteriorUnset;
            if (entered && defect == IndoorDefect.BuildingStopFirstRoom)
            {
                break;
            }
        }

        return hit;
    }

    // Exit portals: −R < d < R, both strict, R = r + EPS (facts §5.1, §6.9); the defect drops the lower bound.
    private static bool Straddles(EnvCell cell, CellPortal portal, ReadOnlySpan<Sphere> spheres, bool oneSided, IndoorDefect defect)
    {
        foreach (var s in spheres)
        {
            float d = portal.Plane.Distance(cell.Frame.GlobalToLocal(s.Center));
            float r = CornerFaults.PlaneRadius(s.Radius, defect);
            bool inclusive = defect == IndoorDefect.ExitStraddleInclusive; // issue 41: the tie counted as a straddle
            if ((oneSided || d > -r || (inclusive && d == -r)) && (d < r || (inclusive && d == r)))
            {
                return true;
            }
        }

        return false;
    }

    // Load hints: this cell's frame, R = r + EPS, PortalSide ⇒ the other cell is on the positive side (facts §5.4).
    private static bool ReachesSide(EnvCell cell, CellPortal portal, ReadOnlySpan<Sphere> spheres, IndoorDefect defect)
    {
        foreach (var s in spheres)
        {
            float d = portal.Plane.Distance(cell.Frame.GlobalToLocal(s.Center));
            float r = CornerFaults.PlaneRadius(s.Radius, defect);
            bool inclusive = defect == IndoorDefect.HintBoundInclusive; // issue 41: the tie counted as reaching
            if ((portal.PortalSide && (d > -r || (inclusive && d == -r))) || (!portal.PortalSide && (d < r || (inclusive && d == r))))
            {
                return true;
            }
        }

        return false;
    }
}
