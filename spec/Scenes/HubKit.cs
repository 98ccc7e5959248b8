using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>Builds hub scenes (<see cref="HubPlan"/>) and their walk: from Q0's middle to near the meeting corner and back.</summary>
internal static class HubKit
{
    // Quadrant i's centre direction (signs of x and y) and its two outer walls' outward normals.
    private static readonly Vector2[] Quadrant = [new(-1, -1), new(1, -1), new(1, 1), new(-1, 1)];
    private static readonly Vector3[][] OuterWalls = [[-Vector3.UnitX, -Vector3.UnitY], [-Vector3.UnitY, Vector3.UnitX], [Vector3.UnitX, Vector3.UnitY], [Vector3.UnitY, -Vector3.UnitX]];

    /// <summary>Builds the scene: the four quadrants (all in the corner's frame), the home block and its eight neighbours loaded.</summary>
    /// <param name="plan">The plan.</param>
    /// <returns>The scene.</returns>
    public static Scene Build(HubPlan plan)
    {
        var size = new Vector3(plan.SizeX, plan.SizeY, 0);
        int levels = plan.Storey ? 2 : 1, flipIndex = 0;
        var portals = new List<(ScenePortal Portal, int Other)>[4 * levels];
        for (int c = 0; c < portals.Length; c++)
        {
            int i = c % 4, level = c / 4;
            var list = new List<(ScenePortal, int)>();
            var q = new Vector3(Quadrant[i], 0);
            var lift = new Vector3(0, 0, level * plan.Height);
            for (int j = 0; j < 4; j++)
            {
                if (plan.Linked(i, j))
                {
                    // The shared wall is the axis plane where the two quadrants' signs differ.
                    var inward = Quadrant[i].X != Quadrant[j].X ? new Vector3(Quadrant[i].X, 0, 0) : new Vector3(0, Quadrant[i].Y, 0);
                    list.Add((Portal(plan, ref flipIndex, inward, ((q - inward) * size / 2) + lift, (ushort)(0x100 + (4 * level) + j)), (4 * level) + j));
                }
            }

            if (levels == 2)
            {
                // The ceiling of a lower quadrant is the floor of the one above it.
                var up = level == 0 ? -Vector3.UnitZ : Vector3.UnitZ;
                int other = level == 0 ? c + 4 : c - 4;
                list.Add((Portal(plan, ref flipIndex, up, (q * size / 2) with { Z = plan.Height }, (ushort)(0x100 + other)), other));
            }

            for (int k = 0; k < 2 && level == 0; k++)
            {
                if (((plan.Exits >> ((2 * i) + k)) & 1) != 0)
                {
                    var outward = OuterWalls[i][k];
                    list.Add((Portal(plan, ref flipIndex, -outward, ((q * size / 2) + (outward * size / 2)) with { Z = 0 }, CellPortal.Outside), -1));
                }
            }

            portals[c] = Shuffle(list, (plan.Order >> (3 * c)) & 7);
        }

        var cells = new List<SceneCell>();
        for (int c = 0; c < portals.Length; c++)
        {
            int i = c % 4, level = c / 4;
            var q = new Vector3(Quadrant[i], 0) * size;
            var box = ScenePiece.FromBox(Vector3.Min(q, Vector3.Zero) with { Z = level == 0 ? -0.5f : plan.Height }, Vector3.Max(q, Vector3.Zero) with { Z = (level + 1) * plan.Height });
            var linked = portals[c].Select(p => p.Other < 0 ? p.Portal : p.Portal with { OtherPortal = (ushort)portals[p.Other].FindIndex(b => b.Other == c) }).ToList();
            // Upper quadrants see every other cell; a lower one its Blind / BlindUp choice.
            var visible = level == 1
                ? Enumerable.Range(0, 8).Where(o => o != c).Select(Id).ToList()
                : [.. Enumerable.Range(0, 4).Where(j => plan.Sees(i, j)).Select(plan.QuadrantId), .. Enumerable.Range(0, 4).Where(j => plan.SeesUp(i, j)).Select(plan.UpperId)];
            cells.Add(new SceneCell(Id(c), plan.Corner, Quaternion.Identity, [box], linked, visible));
        }

        var blocks = new List<LandblockId>();
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                blocks.Add(new LandblockId((byte)(plan.Block.X + dx), (byte)(plan.Block.Y + dy)));
            }
        }

        return new Scene(blocks, [], cells);

        CellId Id(int c) => c < 4 ? plan.QuadrantId(c) : plan.UpperId(c - 4);
    }

    /// <summary>Returns the walk's points in the block frame: Q0's middle, a point inside Q0 <see cref="HubPlan.Inset"/> from both inner walls (below the radius / √2, the body reaches Q2 across the corner), Q0's middle.</summary>
    /// <param name="plan">The plan.</param>
    /// <returns>The points.</returns>
    public static List<Vector3> Route(HubPlan plan)
    {
        float inset = plan.Inset;
        var middle = plan.Corner + new Vector3(-plan.SizeX / 2, -plan.SizeY / 2, 0);
        return [middle, plan.Corner - new Vector3(inset, inset, 0), middle];
    }

    private static ScenePortal Portal(HubPlan plan, ref int flipIndex, Vector3 inward, Vector3 point, ushort other)
    {
        bool flip = ((plan.Flips >> (flipIndex++ % 31)) & 1) != 0;
        return new ScenePortal(CellPlane.Through(flip ? inward : -inward, point), other, PortalSide: !flip);
    }

    // A dat order of the portals: rotated by the low two bits, reversed by the third.
    private static List<(ScenePortal, int)> Shuffle(List<(ScenePortal, int)> list, int key)
    {
        int n = list.Count;
        var rotated = n == 0 ? list : [.. list.Skip(key % n), .. list.Take(key % n)];
        if ((key & 4) != 0)
        {
            rotated.Reverse();
        }

        return rotated;
    }
}
