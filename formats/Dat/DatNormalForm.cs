using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Formats.Dat;

/// <summary>
/// The round-trip normal form (docs/dat-scenes.md, "Round trip"): what read(write(scene)) returns. Pieces come back
/// as the core's unit planes (<see cref="ConvexPiece.Planes"/>), and as boxes when they are six axis planes in box
/// order; portal planes come back as their polygon's plane (unit normal; bit-exact for axis-aligned planes, within
/// float32 rounding otherwise); visible cells in other blocks follow the cell's own block's; buildings come grouped by
/// block, in order of each block's first building.
/// </summary>
public static class DatNormalForm
{
    /// <summary>Returns the normal form.</summary>
    /// <param name="scene">A valid scene.</param>
    /// <returns>The scene as the records give it back (portal planes up to rounding).</returns>
    public static Scene Of(Scene scene)
    {
        var blocks = scene.Buildings.Select(b => b.Block).Distinct().ToList();
        return new Scene(
            scene.Blocks,
            [.. blocks.SelectMany(k => scene.Buildings.Where(b => b.Block == k))],
            [.. scene.Cells.Select(Cell)])
        {
            UnloadedBlocks = scene.UnloadedBlocks,
            UnloadedCells = scene.UnloadedCells,
        };
    }

    /// <summary>Lists the differences between two scenes: exact (float ==) everywhere but portal planes, compared within a tolerance.</summary>
    /// <param name="expected">Usually the normal form of the original.</param>
    /// <param name="actual">Usually read(write(original)).</param>
    /// <param name="tolerance">Tolerance on portal plane normal components and offsets (0: exact).</param>
    /// <returns>The differences (empty when equal).</returns>
    public static List<string> Differences(Scene expected, Scene actual, float tolerance)
    {
        var d = new List<string>();
        void Check(bool ok, string what)
        {
            if (!ok)
            {
                d.Add(what);
            }
        }

        Check(expected.Blocks.SequenceEqual(actual.Blocks), "blocks");
        Check(expected.UnloadedBlocks.SequenceEqual(actual.UnloadedBlocks), "unloaded blocks");
        Check(expected.UnloadedCells.SequenceEqual(actual.UnloadedCells), "unloaded cells");
        Check(expected.Buildings.Count == actual.Buildings.Count, "building count");
        foreach (var (a, b) in expected.Buildings.Zip(actual.Buildings))
        {
            Check(a.Block == b.Block && a.Origin == b.Origin && a.Portals.SequenceEqual(b.Portals), $"building in {a.Block} at {a.Origin}");
        }

        Check(expected.Cells.Count == actual.Cells.Count, "cell count");
        foreach (var (a, b) in expected.Cells.Zip(actual.Cells))
        {
            string at = $"cell {a.Id}";
            Check(a.Id == b.Id && a.Origin == b.Origin && a.Rotation == b.Rotation, at + " id/frame");
            Check(a.Visible.SequenceEqual(b.Visible), at + " visible");
            Check(a.Pieces.Count == b.Pieces.Count && a.Pieces.Zip(b.Pieces).All(p => SamePiece(p.First, p.Second)), at + " pieces");
            Check(a.Portals.Count == b.Portals.Count, at + " portal count");
            foreach (var (p, q) in a.Portals.Zip(b.Portals))
            {
                Check(p.Other == q.Other && p.PortalSide == q.PortalSide && p.OtherPortal == q.OtherPortal, at + " portal fields");
                Check(Near(p.Plane, q.Plane, tolerance), $"{at} portal plane {p.Plane} vs {q.Plane}");
            }
        }

        return d;
    }

    /// <summary>Tests two planes for equality within a tolerance on each normal component and (relative to 1 + |d|) the offset.</summary>
    /// <param name="a">A plane.</param>
    /// <param name="b">A plane.</param>
    /// <param name="tolerance">The tolerance (0: float ==).</param>
    /// <returns>True when near.</returns>
    public static bool Near(CellPlane a, CellPlane b, float tolerance) =>
        MathF.Abs(a.Normal.X - b.Normal.X) <= tolerance && MathF.Abs(a.Normal.Y - b.Normal.Y) <= tolerance && MathF.Abs(a.Normal.Z - b.Normal.Z) <= tolerance
        && MathF.Abs(a.D - b.D) <= tolerance * (1 + MathF.Abs(a.D));

    private static bool SamePiece(ScenePiece a, ScenePiece b) =>
        a.Box is { } x ? b.Box is { } y && x == y : b.Box is null && a.Planes!.SequenceEqual(b.Planes!);

    private static SceneCell Cell(SceneCell c) => c with
    {
        Pieces = [.. c.Pieces.Select(p => p.Box is not null ? p : CellStructPieces.PieceOf(p.ToConvex().Planes))],
        Portals = [.. c.Portals.Select(p => p with { Plane = PolygonPlane.Unit(p.Plane) })],
        Visible = [.. c.Visible.Where(v => v.Landblock == c.Id.Landblock), .. c.Visible.Where(v => v.Landblock != c.Id.Landblock)],
    };
}
