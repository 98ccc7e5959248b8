using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;

namespace AcPhys.Spec.Cases;

/// <summary>
/// The classes of a scene walk's parts queries (<see cref="ScenePartsQueries"/>), from the reference's parts lists:
/// where a part's shape or frame decides a portal or door test, so that a port misreading it answers differently.
/// </summary>
/// <remarks>
/// A plane is "decided" by a part when its sphere gate passes (|d| ≤ r + EPS, facts §5.2, §5.3) and the side of its
/// box's hull (Plane.intersect_box, §5.7) in the cell's frame changes under the misreading. The planes are the portals
/// of every listed env cell and the doors (the env cell's portal) of every listed loaded land cell's building.
/// </remarks>
internal static class ScenePartsClasses
{
    /// <summary>A pitched or rolled part's side of a plane differs from its heading-only box's.</summary>
    public const string Rotated3D = "parts:rotated-3d";

    /// <summary>A part's side of a plane differs from its box centred on the origin.</summary>
    public const string OffCentre = "parts:off-centre-box";

    /// <summary>A part is held in another block's frame than the anchor.</summary>
    public const string OtherBlock = "parts:other-block-frame";

    /// <summary>At a building door of a listed land cell a part's sphere crosses the door's plane while its box lies wholly on one side and overlaps the cell (the box-side pairing decides, facts §7 #14).</summary>
    public const string BoxBesideDoor = "parts:box-beside-door";

    /// <summary>A poking part's box (<see cref="PartShape.Poking"/>) crosses a listed cell's portal or door plane beyond its sphere's reach (its centre farther than r + EPS from the plane).</summary>
    public const string PokingBox = "parts:poking-box";

    /// <summary>A flat part's box is tested at a plane (its sphere gate passes there).</summary>
    public const string FlatBox = "parts:flat-box";

    /// <summary>A long part's box is tested at a plane (its sphere gate passes there).</summary>
    public const string LongBox = "parts:long-box";

    /// <summary>A tidy part's box is tested at a plane (its sphere gate passes there).</summary>
    public const string TidyBox = "parts:tidy-box";

    /// <summary>At a listed env cell's portal a part's sphere straddles the plane (within r + EPS) while its box lies wholly on the cell's own side: the box test alone turns it back (facts §5.2).</summary>
    public const string SphereAcrossBoxNot = "parts:sphere-across-box-not";

    /// <summary>A part's box crosses a listed cell's portal or door plane while its centre lies beyond r + EPS on the side the one-sided gate shuts (facts §5.2, §5.3: the gate decides before the box).</summary>
    public const string BoxAcrossGateShut = "parts:box-across-gate-shut";

    /// <summary>A part's box crosses a listed cell's portal or door plane while its centre lies beyond r + EPS on the side the one-sided gate lets through (the sphere does not straddle, yet the box test runs).</summary>
    public const string BoxAcrossGateOpen = "parts:box-across-gate-open";

    /// <summary>A parts query's anchor names an env cell the scene lacks (<see cref="PartAnchors"/>).</summary>
    public const string AnchorMissingEnv = "parts:anchor-missing-env";

    /// <summary>A parts query's anchor names a landblock id (low word 0xFFFF).</summary>
    public const string AnchorBlockId = "parts:anchor-block-id";

    /// <summary>A parts query's anchor is a land cell of the neighbouring block, across the block line it is near.</summary>
    public const string AnchorBlockEdge = "parts:anchor-block-edge";

    /// <summary>From an indoor anchor an Always2D part's square ±r (facts §3.4) changes the land cells an exit lists: the reference's list differs with the part taken as a box.</summary>
    public const string Always2DOutside = "parts:always2d-outside";

    /// <summary>A part is held in a portal neighbour of the anchor's cell (or a door's env cell of its land cell), in the same block frame (<see cref="PartCells"/>).</summary>
    public const string HeldInNeighbour = "parts:held-in-neighbour";

    /// <summary>A part is held in an env cell of another block than the anchor's, its origin re-based by the block offset (<see cref="PartCells"/>, facts §5.8).</summary>
    public const string HeldOtherBlockCell = "parts:held-other-block-cell";

    // Every corner of a part's hull in a cell's frame lies within √3·Reach·r of its centre (PartShapes).
    private const float HullReach = 1.7321f * PartShapes.Reach + 0.01f;

    /// <summary>Returns the parts classes of a scene walk.</summary>
    /// <param name="w">The scene walk.</param>
    /// <returns>The tags, each once.</returns>
    public static IEnumerable<string> Of(SceneWalk w)
    {
        var queries = ScenePartsQueries.Of(w);
        if (queries.Count == 0)
        {
            return [];
        }

        var scene = SceneBuild.Build(w.Scene);
        var tags = new HashSet<string>();
        foreach (var (_, kind, _) in ScenePartsQueries.Anchors(w))
        {
            tags.Add(kind switch { AnchorKind.MissingEnv => AnchorMissingEnv, AnchorKind.BlockId => AnchorBlockId, _ => AnchorBlockEdge });
        }

        foreach (var (index, parts) in queries)
        {
            if (parts.Any(p => (p.Cell.Value & LandDefs.BlockMask) != (parts[0].Cell.Value & LandDefs.BlockMask)))
            {
                tags.Add(OtherBlock);
            }

            Held(parts, tags);
            var listed = ReferenceAdapter.Instance.FindCellParts(w.Scene, parts, true).Cells;
            if (!tags.Contains(Always2DOutside) && Always2DDecides(w, parts, listed))
            {
                tags.Add(Always2DOutside);
            }

            foreach (var (cell, portal, door) in Planes(scene, listed))
            {
                for (int k = 0; k < parts.Length; k++)
                {
                    Classify(parts[k], PartShapes.Kind(index, k), cell, portal, door, tags);
                }
            }
        }

        return tags;
    }

    /// <summary>Returns whether a part's sphere crosses a door's plane while its box (hull in the cell's frame) lies wholly on one side of it and overlaps the cell.</summary>
    /// <param name="part">The part.</param>
    /// <param name="cell">The env cell behind the door.</param>
    /// <param name="plane">The door's plane (the cell's portal), in the cell's frame.</param>
    /// <returns>True when the box-side pairing decides this part.</returns>
    public static bool BesideDoor(Part part, EnvCell cell, CellPlane plane)
    {
        var box = BoxSide.InFrame(part, cell.Id, cell.Frame);
        return MathF.Abs(Centre(part, cell, plane)) < part.Radius && BoxSide.Of(plane, box) is Sidedness.Positive or Sidedness.Negative && cell.Volume.BoxIntersects(box);
    }

    // Parts held in another env cell than the anchor's: in its block, or in another block.
    private static void Held(Part[] parts, HashSet<string> tags)
    {
        var anchor = parts[0].Cell;
        for (int k = 1; k < parts.Length; k++)
        {
            var cell = parts[k].Cell;
            if (cell.IsEnv && cell != anchor)
            {
                tags.Add((cell.Value & LandDefs.BlockMask) == (anchor.Value & LandDefs.BlockMask) ? HeldInNeighbour : HeldOtherBlockCell);
            }
        }
    }

    // From an env anchor whose list holds land cells (an exit ran add_all_outside_cells), the list with every part taken as a box differs.
    private static bool Always2DDecides(SceneWalk w, Part[] parts, IReadOnlyList<CellId> listed)
    {
        if (!parts[0].Cell.IsEnv || !parts.Any(p => p.Always2D) || !listed.Any(id => id.IsLand))
        {
            return false;
        }

        var boxes = parts.Select(p => p with { Always2D = false }).ToArray();
        return !ReferenceAdapter.Instance.FindCellParts(w.Scene, boxes, true).Cells.SequenceEqual(listed);
    }

    private static void Classify(Part part, PartShape shape, EnvCell cell, CellPortal portal, bool door, HashSet<string> tags)
    {
        var plane = portal.Plane;
        float d = Centre(part, cell, plane), reach = part.Radius + LandDefs.Epsilon;
        if (MathF.Abs(d) > HullReach * part.Radius)
        {
            return; // no hull in any frame reaches the plane
        }

        var side = BoxSide.Of(plane, BoxSide.InFrame(part, cell.Id, cell.Frame));
        if (MathF.Abs(d) > reach)
        {
            // The sphere does not straddle the plane. Transit skips d < −R (PortalSide) or d > R; entry the mirror (facts §5.2, §5.3).
            if (side == Sidedness.Crossing)
            {
                if (shape == PartShape.Poking)
                {
                    tags.Add(PokingBox);
                }

                bool shut = (portal.PortalSide ? d < 0 : d > 0) != door;
                tags.Add(shut ? BoxAcrossGateShut : BoxAcrossGateOpen);
            }

            return; // the sphere gate decides before the box
        }

        if (shape != PartShape.Poking)
        {
            tags.Add(shape switch { PartShape.Flat => FlatBox, PartShape.Long => LongBox, _ => TidyBox });
        }
        if (!door && (portal.PortalSide ? side == Sidedness.Negative : side == Sidedness.Positive))
        {
            tags.Add(SphereAcrossBoxNot);
        }

        var heading = part with { Frame = part.Frame with { Rotation = PartShapes.Heading(part.Frame.Rotation) } };
        if (side != BoxSide.Of(plane, BoxSide.InFrame(heading, cell.Id, cell.Frame)))
        {
            tags.Add(Rotated3D);
        }

        var centred = part with { Bounds = PartShapes.Centred(part.Bounds) };
        if (side != BoxSide.Of(plane, BoxSide.InFrame(centred, cell.Id, cell.Frame)))
        {
            tags.Add(OffCentre);
        }

        if (door && BesideDoor(part, cell, plane))
        {
            tags.Add(BoxBesideDoor);
        }
    }

    // The part's centre's signed distance from a plane of the cell, block offset applied.
    private static float Centre(Part part, EnvCell cell, CellPlane plane) =>
        plane.Distance(cell.Frame.GlobalToLocal(part.Frame.Origin + LandDefs.GetBlockOffset(cell.Id, part.Cell)));

    // Every listed env cell's portals, and every listed loaded land cell's building doors (the env cell's portal).
    private static IEnumerable<(EnvCell Cell, CellPortal Portal, bool Door)> Planes(CellScene scene, IReadOnlyList<CellId> listed)
    {
        foreach (var id in listed)
        {
            if (id.IsEnv && scene.GetEnvCell(id) is { } env)
            {
                foreach (var portal in env.Portals.ToArray())
                {
                    yield return (env, portal, false);
                }
            }
            else if (id.IsLand && scene.IsLoaded(id.Landblock) && scene.GetBuilding(id) is { } building)
            {
                foreach (var door in building.Portals)
                {
                    if (scene.GetEnvCell(id.WithLow(door.OtherCellId)) is { } cell && door.OtherPortalId < cell.Portals.Length)
                    {
                        yield return (cell, cell.Portals[door.OtherPortalId], true);
                    }
                }
            }
        }
    }
}
