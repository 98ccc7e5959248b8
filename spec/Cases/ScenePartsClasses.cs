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
        foreach (var (_, parts) in queries)
        {
            if (parts.Any(p => (p.Cell.Value & LandDefs.BlockMask) != (parts[0].Cell.Value & LandDefs.BlockMask)))
            {
                tags.Add(OtherBlock);
            }

            var listed = ReferenceAdapter.Instance.FindCellParts(w.Scene, parts, true).Cells;
            foreach (var (cell, plane, door) in Planes(scene, listed))
            {
                foreach (var part in parts)
                {
                    Classify(part, cell, plane, door, tags);
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

    private static void Classify(Part part, EnvCell cell, CellPlane plane, bool door, HashSet<string> tags)
    {
        if (MathF.Abs(Centre(part, cell, plane)) > part.Radius + LandDefs.Epsilon)
        {
            return; // the sphere gate decides before the box
        }

        var side = BoxSide.Of(plane, BoxSide.InFrame(part, cell.Id, cell.Frame));
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
    private static IEnumerable<(EnvCell Cell, CellPlane Plane, bool Door)> Planes(CellScene scene, IReadOnlyList<CellId> listed)
    {
        foreach (var id in listed)
        {
            if (id.IsEnv && scene.GetEnvCell(id) is { } env)
            {
                foreach (var portal in env.Portals.ToArray())
                {
                    yield return (env, portal.Plane, false);
                }
            }
            else if (id.IsLand && scene.IsLoaded(id.Landblock) && scene.GetBuilding(id) is { } building)
            {
                foreach (var door in building.Portals)
                {
                    if (scene.GetEnvCell(id.WithLow(door.OtherCellId)) is { } cell && door.OtherPortalId < cell.Portals.Length)
                    {
                        yield return (cell, cell.Portals[door.OtherPortalId].Plane, true);
                    }
                }
            }
        }
    }
}
