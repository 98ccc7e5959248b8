using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// Independent geometry for scene invariants: exact containment in a cell's pieces with a margin (no EPS, no BSP), the
/// land cell under a world point in double, and what a scene declares as loaded.
/// </summary>
public static class SceneOracle
{
    /// <summary>Maps a point in a cell id's block frame into world metres (double).</summary>
    /// <param name="frame">The id whose block frame <paramref name="p"/> is in.</param>
    /// <param name="p">The point.</param>
    /// <returns>World x, y.</returns>
    public static (double X, double Y) World(CellId frame, Vector3 p) => ((192.0 * frame.BlockX) + p.X, (192.0 * frame.BlockY) + p.Y);

    /// <summary>Returns how deep a point lies inside a cell (min over the pieces' max of plane distances): &gt; 0 inside, &lt; 0 outside.</summary>
    /// <param name="cell">The cell.</param>
    /// <param name="frame">The id whose block frame <paramref name="p"/> is in.</param>
    /// <param name="p">The point.</param>
    /// <returns>Signed depth, metres.</returns>
    public static double Depth(SceneCell cell, CellId frame, Vector3 p)
    {
        var (wx, wy) = World(frame, p);
        var inBlock = new Vector3((float)(wx - (192.0 * cell.Id.BlockX)), (float)(wy - (192.0 * cell.Id.BlockY)), p.Z);
        var local = new Frame(cell.Origin, cell.Rotation).GlobalToLocal(inBlock);
        double best = double.NegativeInfinity;
        foreach (var piece in cell.Pieces)
        {
            var convex = piece.ToConvex();
            double worst = double.PositiveInfinity;
            foreach (var plane in convex.Planes)
            {
                worst = Math.Min(worst, plane.Distance(local));
            }

            best = Math.Max(best, worst);
        }

        return best;
    }

    /// <summary>Tests whether a cell is loaded: declared with geometry and in a loaded block.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="id">A cell id.</param>
    /// <returns>True when loaded.</returns>
    public static bool IsLoadedEnv(Scene scene, CellId id) => scene.Blocks.Contains(id.Landblock) && scene.Cells.Any(c => c.Id == id);

    /// <summary>Tests whether an id names something a query may return as a loaded cell (a loaded env cell, or a land cell of a loaded block).</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="id">An id.</param>
    /// <returns>True when loaded.</returns>
    public static bool IsLoaded(Scene scene, CellId id) => id.IsLand ? scene.Blocks.Contains(id.Landblock) : IsLoadedEnv(scene, id);

    /// <summary>Tests whether the containing pick may choose a cell: retail's point_in_cell is false for a cell without portals (facts §5.5, §7 #13), ACE's is not.</summary>
    /// <param name="cell">The cell.</param>
    /// <param name="fidelity">The declared indoor fidelity.</param>
    /// <returns>True when the cell's volume decides.</returns>
    public static bool Pickable(SceneCell cell, IndoorFidelity fidelity) => cell.Portals.Count > 0 || fidelity.AceNoPortalGuard;

    /// <summary>Whether a cell has a portal (not an exit) to another env cell of its block (facts §5.1, §5.4).</summary>
    /// <param name="cell">The cell.</param>
    /// <param name="id">The other cell.</param>
    /// <returns>True when one of its portals leads there.</returns>
    public static bool LeadsTo(SceneCell cell, CellId id) => cell.Portals.Any(p => !p.IsExit && cell.Id.WithLow(p.Other) == id);

    /// <summary>Returns the declared cell of an id, or null.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="id">An id.</param>
    /// <returns>The cell.</returns>
    public static SceneCell? Cell(Scene scene, CellId id) => scene.Cells.FirstOrDefault(c => c.Id == id);

    /// <summary>Returns the loaded env cells whose volume contains the point by at least a margin.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="frame">The frame id.</param>
    /// <param name="p">The point.</param>
    /// <param name="margin">Metres.</param>
    /// <returns>The cells.</returns>
    public static IEnumerable<SceneCell> Inside(Scene scene, CellId frame, Vector3 p, double margin) =>
        scene.Cells.Where(c => scene.Blocks.Contains(c.Id.Landblock) && Depth(c, frame, p) >= margin);

    /// <summary>Tests whether the point is outside every declared cell with geometry by at least a margin.</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="frame">The frame id.</param>
    /// <param name="p">The point.</param>
    /// <param name="margin">Metres.</param>
    /// <returns>True when clear of every cell.</returns>
    public static bool OutsideAll(Scene scene, CellId frame, Vector3 p, double margin) => scene.Cells.All(c => Depth(c, frame, p) <= -margin);

    /// <summary>Returns the global lcoord of the land cell under a world point, or null off the map.</summary>
    /// <param name="x">World x.</param>
    /// <param name="y">World y.</param>
    /// <returns>The lcoord.</returns>
    public static (int X, int Y)? LandAt(double x, double y)
    {
        double gx = Math.Floor(x / 24), gy = Math.Floor(y / 24);
        return gx >= 0 && gy >= 0 && gx < Oracle.MapCells && gy < Oracle.MapCells ? ((int)gx, (int)gy) : null;
    }

    /// <summary>Returns the distance (metres, per axis) from a world point to a land cell's closed square; 0 inside.</summary>
    /// <param name="cell">A land cell.</param>
    /// <param name="x">World x.</param>
    /// <param name="y">World y.</param>
    /// <returns>The distance.</returns>
    public static double LandDistance(CellId cell, double x, double y)
    {
        var (gx, gy) = Oracle.LcoordOf(cell);
        double dx = Math.Max(Math.Max((24.0 * gx) - x, x - (24.0 * (gx + 1))), 0);
        double dy = Math.Max(Math.Max((24.0 * gy) - y, y - (24.0 * (gy + 1))), 0);
        return Math.Max(dx, dy);
    }

    /// <summary>Tests whether a world point is on the map with a margin.</summary>
    /// <param name="x">World x.</param>
    /// <param name="y">World y.</param>
    /// <param name="margin">Metres.</param>
    /// <returns>True when inside.</returns>
    public static bool OnMap(double x, double y, double margin) =>
        x >= margin && y >= margin && x < (24.0 * Oracle.MapCells) - margin && y < (24.0 * Oracle.MapCells) - margin;
}
