using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Props.Dat;

/// <summary>
/// Scenes the scene generators do not make: cells of several pieces (L shapes as two boxes, stairs as boxes), rotated
/// boxes as plane lists, and portals on oblique planes; one block, a chain of 1–4 cells linked by portals, exits.
/// </summary>
internal static class MultiPieceScenes
{
    /// <summary>Gets the generator.</summary>
    public static Gen<Scene> Scenes { get; } =
        from count in Gen.Choose(1, 4)
        from shapes in Gen.ArrayOf(Shape, count)
        from yaw in Gen.Choose(0, 63)
        from flips in Gen.Choose(0, 255)
        select Build(shapes, yaw * MathF.PI / 32, flips);

    private static Gen<ScenePiece[]> Shape => Gen.Frequency(
        (2, from w in Size from d in Size select new[] { ScenePiece.FromBox(Vector3.Zero, new Vector3(w, d / 2, 3)), ScenePiece.FromBox(Vector3.Zero, new Vector3(w / 2, d, 3)) }),
        (2, from w in Size
            from d in Size
            from steps in Gen.Choose(2, 4)
            select Enumerable.Range(0, steps).Select(i => ScenePiece.FromBox(new Vector3(i * w / steps, 0, 0), new Vector3(w, d, i + 1f))).ToArray()),
        (1, from w in Size from d in Size select new[] { ScenePiece.FromBox(Vector3.Zero, new Vector3(w, d, 3)) }),
        (2, from w in Size
            from d in Size
            from a in Gen.Choose(1, 63)
            from extra in Gen.Elements(true, false)
            select extra ? new[] { Rotated(w, d, a * MathF.PI / 64), ScenePiece.FromBox(Vector3.Zero, new Vector3(w, d, 2)) } : new[] { Rotated(w, d, a * MathF.PI / 64) }));

    private static Gen<float> Size => Gen.Choose(8, 40).Select(i => i / 4f);

    // A w×d×3 box turned by `angle` about z, as six planes (N scaled by 2 so the reader's unit planes differ from the input).
    private static ScenePiece Rotated(float w, float d, float angle)
    {
        var q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, angle);
        var centre = new Vector3(w / 2, d / 2, 1.5f);
        var half = new Vector3(w / 2, d / 2, 1.5f);
        var planes = new List<CellPlane>();
        foreach (var (axis, h) in new[] { (Vector3.UnitX, half.X), (Vector3.UnitY, half.Y), (Vector3.UnitZ, half.Z) })
        {
            var n = Vector3.Transform(axis, q);
            planes.Add(new CellPlane(2 * n, -2 * (Vector3.Dot(n, centre) - h)));
            planes.Add(new CellPlane(-2 * n, 2 * (Vector3.Dot(n, centre) + h)));
        }

        return new ScenePiece(null, planes);
    }

    private static Scene Build(ScenePiece[][] shapes, float yaw, int flips)
    {
        var block = new LandblockId(0x40, 0x41);
        var rotation = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw);
        var cells = new List<SceneCell>();
        for (int i = 0; i < shapes.Length; i++)
        {
            var id = new CellId(block.X, block.Y, (ushort)(0x0100 + i));
            var bounds = ConvexPiece.BoundsOf([.. shapes[i].Select(p => p.ToConvex())]);
            var portals = new List<ScenePortal>
            {
                // An exit on the min-x face (axis plane) and one oblique exit through the middle.
                new(new CellPlane(-Vector3.UnitX, bounds.Min.X), CellPortal.Outside, (flips & 1) == 0),
                new(CellPlane.Through(new Vector3(1, 2, 0.5f), (bounds.Min + bounds.Max) / 2), CellPortal.Outside, (flips & 2) == 0),
            };
            if (i + 1 < shapes.Length)
            {
                portals.Add(new ScenePortal(new CellPlane(Vector3.UnitX, -bounds.Max.X), (ushort)(0x0101 + i), (flips & 4) == 0, 2));
            }

            if (i > 0)
            {
                portals.Insert(2, new ScenePortal(new CellPlane(-Vector3.UnitX, bounds.Min.X), (ushort)(0x00FF + i), (flips & 8) == 0, 2));
            }

            var visible = Enumerable.Range(0, shapes.Length).Where(k => k != i).Select(k => new CellId(block.X, block.Y, (ushort)(0x0100 + k))).ToList();
            cells.Add(new SceneCell(id, new Vector3(20 + (30 * i), 40, 0), rotation, shapes[i], portals, visible));
        }

        return new Scene([block], [], cells);
    }
}
