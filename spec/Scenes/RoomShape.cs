using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>The shape of a room as a union of convex pieces inside the room's box (docs/indoor.md, "Unions and the positive chain").</summary>
public enum RoomShape
{
    /// <summary>One box piece: the BSP and the AABB agree away from the tolerance bands.</summary>
    Box,

    /// <summary>Two boxes: the south 60 % of the room at full width, and the west 60 % at full depth (an L with its corner at the south-west).</summary>
    LShape,

    /// <summary>Three boxes stepping up along +x: full length a third high, the east two thirds two thirds high, the east third full height.</summary>
    Stairs,
}

/// <summary>Reshapes the box rooms of a scene into unions, keeping the box, the portals and the ids (for the AABB-vs-BSP measurements).</summary>
public static class RoomShapes
{
    /// <summary>Gets the shapes, in table order.</summary>
    public static IReadOnlyList<RoomShape> All { get; } = [RoomShape.Box, RoomShape.LShape, RoomShape.Stairs];

    /// <summary>Returns the shape's name as the tables print it.</summary>
    /// <param name="shape">The shape.</param>
    /// <returns>box, l-shape or stairs.</returns>
    public static string Name(RoomShape shape) => shape switch
    {
        RoomShape.LShape => "l-shape",
        RoomShape.Stairs => "stairs",
        _ => "box",
    };

    /// <summary>Returns the pieces of a shape filling the box min..max; piece 0 is the one retail's BSP queries see.</summary>
    /// <param name="shape">The shape.</param>
    /// <param name="min">The room box's minimum corner.</param>
    /// <param name="max">The room box's maximum corner.</param>
    /// <returns>The pieces; their bounding box is min..max.</returns>
    public static IReadOnlyList<ScenePiece> Pieces(RoomShape shape, Vector3 min, Vector3 max)
    {
        var size = max - min;
        return shape switch
        {
            RoomShape.LShape =>
            [
                ScenePiece.FromBox(min, new Vector3(max.X, min.Y + (0.6f * size.Y), max.Z)),
                ScenePiece.FromBox(min, new Vector3(min.X + (0.6f * size.X), max.Y, max.Z)),
            ],
            RoomShape.Stairs =>
            [
                ScenePiece.FromBox(min, new Vector3(max.X, max.Y, min.Z + (size.Z / 3))),
                ScenePiece.FromBox(new Vector3(min.X + (size.X / 3), min.Y, min.Z), new Vector3(max.X, max.Y, min.Z + (2 * size.Z / 3))),
                ScenePiece.FromBox(new Vector3(min.X + (2 * size.X / 3), min.Y, min.Z), max),
            ],
            _ => [ScenePiece.FromBox(min, max)],
        };
    }

    /// <summary>Returns the scene with every box cell reshaped (see the per-cell overload).</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="shape">The shape of every room.</param>
    /// <returns>The reshaped scene.</returns>
    public static Scene Shaped(Scene scene, RoomShape shape) => Shaped(scene, _ => shape);

    /// <summary>
    /// Returns the scene with each cell made of box pieces reshaped by a per-cell choice inside the box they fill (a
    /// generated L room or stairwell is first taken back to its bounding box, so <see cref="RoomShape.Box"/> really
    /// means box rooms); cells with plane pieces are kept.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="shapeOf">The shape of a cell.</param>
    /// <returns>The reshaped scene.</returns>
    public static Scene Shaped(Scene scene, Func<CellId, RoomShape> shapeOf) => scene with
    {
        Cells = [.. scene.Cells.Select(c => c.Pieces.All(p => p.Box is not null)
            ? c with { Pieces = Pieces(shapeOf(c.Id), c.Pieces.Aggregate(c.Pieces[0].Box!.Value.Min, (m, p) => Vector3.Min(m, p.Box!.Value.Min)), c.Pieces.Aggregate(c.Pieces[0].Box!.Value.Max, (m, p) => Vector3.Max(m, p.Box!.Value.Max))) }
            : c)],
    };
}
