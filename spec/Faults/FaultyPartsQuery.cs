using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// The parts cell list over a scene (core's <see cref="ScenePartsQuery"/>, retail) re-stated with one defect of
/// <see cref="PartsIndoorFaults"/> or <see cref="PartsShapeFaults"/> in place, so the core keeps no fault switches. With no defect it answers as core
/// (props/Indoor/PartsFaultsAreCaught checks it).
/// </summary>
internal static class FaultyPartsQuery
{
    private static readonly Frame Identity = new(Vector3.Zero, Quaternion.Identity);

    /// <summary>Runs the faulty parts cell list.</summary>
    /// <param name="array">The array (reset here).</param>
    /// <param name="scene">The scene.</param>
    /// <param name="given">The parts as asked.</param>
    /// <param name="loadCells">True for a transition.</param>
    /// <param name="fault">The defect, or null for none.</param>
    /// <returns>HitsInteriorCell.</returns>
    public static bool FindCellList(CellArray array, IScene scene, Part[] given, bool loadCells, PlantedFault? fault)
    {
        array.Reset();
        if (given.Length == 0)
        {
            return false;
        }

        Part[] parts = given;
        Part[] probing = fault == PartsIndoorFaults.FirstPartOnly ? parts[..1] : parts;
        Part[] entering = fault == PartsIndoorFaults.FirstPartOnly || fault == PartsIndoorFaults.BuildingAnchorOnly ? parts[..1] : parts;
        var defects = new Defects(fault == PartsIndoorFaults.BoxUntransformed, fault == PartsIndoorFaults.OrderLost, fault);
        var position = parts[0].Cell;
        bool hits = false;
        bool indoor = position.IsIndoorByLowWord;
        bool visible;
        if (indoor)
        {
            visible = scene.GetEnvCell(position) is not null;
            if (!visible && fault == PartsShapeFaults.MissingAnchorEmpty)
            {
                return false; // the port bails out on an anchor cell it cannot find
            }

            hits = true;
            array.Add(position, visible);
        }
        else
        {
            visible = position.IsLand && scene.IsLoaded(position.Landblock);
            OutdoorParts.AddAllOutsideCells(array, parts, position, scene);
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

                if (entry.Id.IsEnv && scene.GetEnvCell(entry.Id) is { } env)
                {
                    Transit(array, scene, env, probing, parts, defects);
                }
                else if (entry.Id.IsLand)
                {
                    OutdoorParts.AddAllOutsideCells(array, parts, entry.Id, scene);
                    if (scene.GetBuilding(entry.Id) is { } building)
                    {
                        foreach (var door in building.Portals)
                        {
                            if (scene.GetEnvCell(entry.Id.WithLow(door.OtherCellId)) is { } cell)
                            {
                                hits |= Enter(array, scene, cell, door.OtherPortalId, entering, probing, parts, defects);
                            }
                        }
                    }
                }
            }
        }

        if (!loadCells && indoor && visible)
        {
            SceneQuery.FilterVisible(array, scene, position);
        }

        return hits;
    }

    // The box a port tests: in the cell's frame (retail), or left in the part's block frame (parts-box-untransformed).
    private static Box BoxIn(Part part, EnvCell cell, bool untransformed) =>
        untransformed ? BoxSide.InFrame(part, part.Cell, Identity) : BoxSide.InFrame(part, cell.Id, cell.Frame);

    private static float Distance(Part part, EnvCell cell, CellPortal portal) =>
        portal.Plane.Distance(cell.Frame.GlobalToLocal(part.Frame.Origin + LandDefs.GetBlockOffset(cell.Id, part.Cell)));

    // EnvTransitParts.FindTransitCells, facts §5.2, over the probing parts; the outdoor cells by all parts.
    private static void Transit(CellArray array, IScene scene, EnvCell cell, Part[] probing, Part[] parts, Defects defects)
    {
        bool untransformed = defects.Untransformed, partMajor = defects.PartMajor;
        bool checkOutside = false;
        var portals = cell.Portals.ToArray();
        var decided = new bool[portals.Length];
        int outer = partMajor ? probing.Length : portals.Length, inner = partMajor ? portals.Length : probing.Length;
        for (int o = 0; o < outer; o++)
        {
            for (int n = 0; n < inner; n++)
            {
                int k = partMajor ? n : o;
                var portal = portals[k];
                var part = probing[partMajor ? o : n];
                if (decided[k])
                {
                    continue; // parts-order-lost: a portal an earlier part decided is not probed again
                }

                bool Decide()
                {
                    decided[k] = partMajor;
                    return !partMajor; // portal-major: the part loop ends (retail's break); part-major: the next portal
                }

                float r = part.Radius + LandDefs.Epsilon, d = Distance(part, cell, portal);
                var side = BoxSide.Of(portal.Plane, BoxIn(part, cell, untransformed));
                if (!defects.Gate(side, portal.PortalSide ? d < -r : d > r, MathF.Abs(d) > r))
                {
                    continue;
                }

                if (defects.Fault != PartsShapeFaults.BoxSideSkipped && ((side == Sidedness.Positive && !portal.PortalSide) || (side == Sidedness.Negative && portal.PortalSide)))
                {
                    continue;
                }

                if (portal.LeadsOutside(default))
                {
                    checkOutside = true;
                    if (Decide())
                    {
                        break;
                    }

                    continue;
                }

                var otherId = cell.Id.WithLow(portal.OtherCellId);
                if (scene.GetEnvCell(otherId) is not { } other)
                {
                    array.Add(otherId, false);
                    if (Decide())
                    {
                        break;
                    }

                    continue;
                }

                if (defects.Fault == PartsShapeFaults.NeighbourBySphere ? SphereReaches(part, other) : other.Volume.BoxIntersects(BoxIn(part, other, untransformed)))
                {
                    array.Add(other.Id, true);
                    if (Decide())
                    {
                        break;
                    }
                }
            }
        }

        if (checkOutside)
        {
            OutdoorParts.AddAllOutsideCells(array, parts, cell.Id, scene);
        }
    }

    // EnvTransitParts.CheckBuildingTransit, facts §5.3 (retail box-side pairing), over the entering parts.
    private static bool Enter(CellArray array, IScene scene, EnvCell cell, ushort portalId, Part[] entering, Part[] probing, Part[] parts, Defects defects)
    {
        if (portalId == BldPortal.None || portalId >= cell.Portals.Length)
        {
            return false;
        }

        var portal = cell.Portals[portalId];
        foreach (var part in entering)
        {
            float r = part.Radius + LandDefs.Epsilon, d = Distance(part, cell, portal);
            var box = BoxIn(part, cell, defects.Untransformed);
            var side = BoxSide.Of(portal.Plane, box);
            if (!defects.Gate(side, portal.PortalSide ? d > r : d < -r, MathF.Abs(d) > r))
            {
                continue;
            }

            var inside = portal.PortalSide ? Sidedness.Negative : Sidedness.Positive;
            if ((side == Sidedness.Crossing || side == inside) && cell.Volume.BoxIntersects(box))
            {
                array.Add(cell.Id, true);
                Transit(array, scene, cell, probing, parts, defects);
                return true;
            }
        }

        return false;
    }

    // parts-neighbour-by-sphere: the part's sphere in the neighbour's frame (block offset applied), as §5.1's spheres.
    private static bool SphereReaches(Part part, EnvCell other) =>
        other.Volume.SphereIntersects(new Sphere(other.Frame.GlobalToLocal(part.Frame.Origin + LandDefs.GetBlockOffset(other.Id, part.Cell)), part.Radius)) != BoundingType.Outside;

    // The defects the transit and entry checks carry.
    private readonly record struct Defects(bool Untransformed, bool PartMajor, PlantedFault? Fault)
    {
        // Whether the part goes on to the box test: retail's one-sided gate (facts §5.2, §5.3), a two-sided one, or the box first (a crossing box passes).
        public bool Gate(Sidedness side, bool shut, bool apart) =>
            Fault == PartsShapeFaults.GateTwoSided ? !apart
            : (Fault == PartsShapeFaults.BoxBeforeGate && side == Sidedness.Crossing) || !shut;
    }
}
