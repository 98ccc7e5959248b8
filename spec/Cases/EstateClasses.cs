using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Scenes;

namespace AcPhys.Spec.Cases;

/// <summary>The distribution classes of an estate walk (shown by the verify table and FsCheck's Collect).</summary>
internal static class EstateClasses
{
    /// <summary>Gets every estate class tag, in report order.</summary>
    public static IReadOnlyList<string> All { get; } =
    [
        "frame:per-cell", "frame:general-rotation", "doors:1", "doors:2", "doors:3", "doors:4", "door:invalid-marker", "graph:branch",
        "graph:loop", "storey:stacked", "cell:overlap-stairwell", "cell:multi-piece", "buildings:2+", "place:block-corner",
        "place:building-across-line", "mover:neighbour-block", "dungeon:cross-block", "cell:unloaded-middle", "body:3-spheres",
        "body:mixed-radii", "step:two-portals", "see:partial", "wall:sealed", "walk:facade", "walk:facade-sealed-seam", "walk:second-piece-only", "walk:door-room-second-piece",
    ];

    /// <summary>Returns the classes of an estate walk.</summary>
    /// <param name="r">The recipe (with an estate).</param>
    /// <param name="w">The built walk.</param>
    /// <returns>Tags.</returns>
    public static IEnumerable<string> Of(SceneRecipe r, SceneWalk w)
    {
        var p = r.Estate!;
        var scene = w.Scene;
        var home = scene.Cells.Where(c => c.Id.Landblock == p.Block && c.Id.Low < 0x110).ToList();
        if (p.OwnFrames && home.Select(c => (c.Origin, c.Rotation)).Distinct().Count() > 1)
        {
            yield return "frame:per-cell";
        }

        if (p.Tilt != Vector2.Zero)
        {
            yield return "frame:general-rotation";
        }

        var main = scene.Buildings[0];
        yield return $"doors:{main.Portals.Count}";
        if (main.Portals.Any(b => b.Portal == 0xFFFF))
        {
            yield return "door:invalid-marker";
        }

        if (p.Rooms >= 4)
        {
            yield return p.Layout switch { EstateLayout.Branch => "graph:branch", EstateLayout.Ring => "graph:loop", _ => "graph:row" };
        }

        if (p.Storey)
        {
            yield return "storey:stacked";
        }

        if (p.Storey && p.Stairwell)
        {
            yield return "cell:overlap-stairwell";
        }

        if (home.Any(c => c.Pieces.Count > 1))
        {
            yield return "cell:multi-piece";
        }

        if (scene.Buildings.Count >= 2)
        {
            yield return "buildings:2+";
        }

        static double Line(double v) => Math.Abs(v - (192 * Math.Round(v / 192)));
        if (Line(p.WorldX) <= 30 && Line(p.WorldY) <= 30)
        {
            yield return "place:block-corner";
        }

        if (AcrossLine(p, home))
        {
            yield return "place:building-across-line";
        }

        if (w.Walk.StartCell.Landblock != p.Block)
        {
            yield return "mover:neighbour-block";
        }

        if (p.Lead > 0)
        {
            yield return "dungeon:cross-block";
        }

        if (scene.UnloadedCells.Count > 0)
        {
            yield return "cell:unloaded-middle";
        }

        var body = w.Walk.Body;
        if (body.Count == 3)
        {
            yield return "body:3-spheres";
        }

        if (body.Select(b => b.Radius).Distinct().Count() > 1)
        {
            yield return "body:mixed-radii";
        }

        if (p.Vestibule && w.Walk.Steps.Any(s => s.Length() > EstatePlan.VestibuleDepth))
        {
            yield return "step:two-portals";
        }

        if (p.SeeDepth > 0 && home.Count > p.SeeDepth + 1)
        {
            yield return "see:partial";
        }

        var at = EstateGrid.Positions(p.Layout, Math.Clamp(p.Rooms, 1, 6));
        var links = EstateGrid.Links(at);
        var open = EstateGrid.OpenLinks(at, p.SealedWalls);
        if (open.Count < links.Count)
        {
            yield return "wall:sealed";
        }

        var doorRooms = main.Portals.Where(b => b.Portal != 0xFFFF).Select(b => b.Cell).ToHashSet(); // valid doors' low words
        if (r.Route == SceneRoute.Facade)
        {
            yield return "walk:facade";
            var passed = FacadeRooms(r, w, at);
            bool DoorRoomPassed(int room) => passed.Contains(room) && doorRooms.Contains((ushort)(0x100 + room));
            if (links.Except(open).Any(l => DoorRoomPassed(l.A) && DoorRoomPassed(l.B)))
            {
                yield return "walk:facade-sealed-seam";
            }
        }

        var secondPieceOnly = SecondPieceOnly(p, w, home);
        if (secondPieceOnly.Count > 0)
        {
            yield return "walk:second-piece-only";
        }

        if (secondPieceOnly.Overlaps(doorRooms))
        {
            yield return "walk:door-room-second-piece";
        }
    }

    // Sphere 0's centres along the walk in the building block's frame.
    private static IEnumerable<Vector3> Centres(EstatePlan p, SceneWalk w)
    {
        var start = w.Walk.StartCell.Landblock;
        var pos = w.Walk.Start + new Vector3(192f * (start.X - p.Block.X), 192f * (start.Y - p.Block.Y), 0) + w.Walk.Body[0].Offset;
        yield return pos;
        foreach (var step in w.Walk.Steps)
        {
            pos += new Vector3(step, 0);
            yield return pos;
        }
    }

    // The L rooms (low words) whose second piece sphere 0 reaches without reaching their first (the two differ there: facts §5.7).
    private static HashSet<ushort> SecondPieceOnly(EstatePlan p, SceneWalk w, List<SceneCell> home)
    {
        var ls = home.Where(c => c.Pieces.Count > 1).Select(c => (c.Id.Low, Frame: new Frame(c.Origin, c.Rotation), First: c.Pieces[0].ToConvex().Bounds, Second: c.Pieces[1].ToConvex().Bounds)).ToList();
        float r = w.Walk.Body[0].Radius;
        var reached = new HashSet<ushort>();
        if (ls.Count == 0)
        {
            return reached;
        }

        foreach (var g in Centres(p, w))
        {
            foreach (var l in ls)
            {
                var q = l.Frame.GlobalToLocal(g);
                if (Distance(l.Second, q) < r && Distance(l.First, q) > r + 0.02f)
                {
                    reached.Add(l.Low);
                }
            }
        }

        return reached;
    }

    private static float Distance(Box b, Vector3 q) => Vector3.Distance(Vector3.Clamp(q, b.Min, b.Max), q);

    // The grid rooms a facade walk's sphere 0 comes within its radius of (distance to the room's footprint, building frame).
    private static HashSet<int> FacadeRooms(SceneRecipe r, SceneWalk w, (int X, int Y)[] at)
    {
        var p = r.Estate!;
        var passed = new HashSet<int>();
        foreach (var g in Centres(p, w))
        {
            var q = p.Frame.GlobalToLocal(g);
            for (int i = 0; i < at.Length; i++)
            {
                var min = new Vector2(at[i].X * p.Width, at[i].Y * p.Depth);
                if (Vector2.Distance(Vector2.Clamp(new Vector2(q.X, q.Y), min, min + new Vector2(p.Width, p.Depth)), new Vector2(q.X, q.Y)) < r.Radius)
                {
                    passed.Add(i);
                }
            }
        }

        return passed;
    }

    // Whether the building's cells reach into more than one block (their pieces' corners, world metres).
    private static bool AcrossLine(EstatePlan p, List<SceneCell> cells)
    {
        var blocks = new HashSet<(double, double)>();
        foreach (var c in cells)
        {
            var frame = new Frame(c.Origin, c.Rotation);
            var b = c.Pieces[0].ToConvex().Bounds;
            foreach (var q in new[] { b.Min, b.Max, new Vector3(b.Min.X, b.Max.Y, 0), new Vector3(b.Max.X, b.Min.Y, 0) })
            {
                var g = frame.LocalToGlobal(q);
                blocks.Add((Math.Floor(((192.0 * p.Block.X) + g.X) / 192), Math.Floor(((192.0 * p.Block.Y) + g.Y) / 192)));
            }
        }

        return blocks.Count > 1;
    }
}
