namespace AcPhys.Formats.Dat;

/// <summary>A CellStruct of an Environment record (dat-records.md, CellStruct); keyed by the EnvCell's cell structure.</summary>
/// <param name="Key">The key.</param>
/// <param name="Vertices">Vertices (ids unique).</param>
/// <param name="Polygons">Polygons (ids unique).</param>
/// <param name="PortalPolygonIds">The ids of the portal polygons.</param>
/// <param name="CellBsp">The cell BSP.</param>
/// <param name="PhysicsPolygons">Physics polygons (ids unique).</param>
/// <param name="PhysicsBsp">The physics BSP.</param>
/// <param name="DrawingBsp">The drawing BSP, or null (hasDrawingBSP = 0).</param>
public sealed record CellStructRecord(
    uint Key,
    IReadOnlyList<DatVertex> Vertices,
    IReadOnlyList<DatPolygon> Polygons,
    IReadOnlyList<ushort> PortalPolygonIds,
    BspNode CellBsp,
    IReadOnlyList<DatPolygon> PhysicsPolygons,
    BspNode PhysicsBsp,
    BspNode? DrawingBsp);
