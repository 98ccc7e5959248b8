using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>
/// Portal polygons for a scene given by planes (issue #29): each portal gets the quad the dat export writes for it
/// (<see cref="CellStructBuilder.PortalQuad"/>: in the portal's plane, covering the cell's bounds, wound so its derived
/// plane is the portal plane), so the scene JSON can carry the polygons a port derives its planes from.
/// </summary>
public static class PortalPolygons
{
    /// <summary>Returns the scene with every env cell's portals carrying their polygons.</summary>
    /// <param name="scene">The scene.</param>
    /// <returns>The same scene, portals with <see cref="ScenePortal.Polygon"/> set.</returns>
    public static Scene With(Scene scene) => scene with
    {
        Cells = [.. scene.Cells.Select(cell =>
        {
            var bounds = ConvexPiece.BoundsOf([.. cell.Pieces.Select(p => p.ToConvex())]);
            return cell with { Portals = [.. cell.Portals.Select(p => p with { Polygon = CellStructBuilder.PortalQuad(PolygonPlane.Unit(p.Plane), bounds) })] };
        })],
    };
}
