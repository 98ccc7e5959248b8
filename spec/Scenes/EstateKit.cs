using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>
/// Builds estate scenes (see <see cref="EstatePlan"/>). Geometry is drafted in each building's frame — rooms are grid
/// boxes, every shared wall a portal pair unless sealed, doors exit portals — then mapped into each cell's own frame
/// (<see cref="CellPlacement"/>), so neighbouring cells have different local coordinates but the same world walls.
/// </summary>
internal static class EstateKit
{
    /// <summary>Builds the scene and its route helpers.</summary>
    /// <param name="plan">The plan.</param>
    /// <returns>The model.</returns>
    public static EstateModel Build(EstatePlan plan)
    {
        var at = EstateGrid.Positions(plan.Layout, Math.Clamp(plan.Rooms, 1, 6));
        var main = new EstateDraft(plan.Block, 0x100, plan.Frame, plan.Width, plan.Depth, plan.Flips);
        for (int i = 0; i < at.Length; i++)
        {
            main.Room(at[i], plan.OwnFrames, (plan.CellTurns >> (2 * i)) & 3);
        }

        foreach (var (a, b, side) in EstateGrid.OpenLinks(at, plan.SealedWalls))
        {
            main.Link(a, b, main.WallPoint(at[a], side), -Outward(side));
        }

        var doors = ChooseDoors(plan, at);
        var doorList = new List<EstateDoor>();
        var used = new HashSet<(int, GridSide)>();
        for (int j = 0; j < doors.Count; j++)
        {
            var (room, side) = doors[j];
            used.Add((room, side));
            bool valid = j == Entry(plan, doors.Count) || ((plan.InvalidDoors >> j) & 1) == 0;
            var wall = main.WallPoint(at[room], side);
            var point = wall;
            if (plan.Vestibule && j == Entry(plan, doors.Count))
            {
                point = wall + (Outward(side) * EstatePlan.VestibuleDepth);
                int v = main.Vestibule(room, at[room], side, plan.OwnFrames);
                main.Link(room, v, wall, -Outward(side));
                main.Door(v, point, Outward(side), valid);
            }
            else
            {
                main.Door(room, wall, Outward(side), valid);
            }

            doorList.Add(new EstateDoor(room, side, valid, point with { Z = 0 }, Outward(side)));
        }

        for (int i = 0; i < at.Length; i++)
        {
            if (((plan.LShapes >> i) & 1) != 0 && !(i == 0 && plan.Storey))
            {
                var notch = EstateGrid.FreeSides(at, i).FirstOrDefault(s => !used.Contains((i, s)), (GridSide)(-1));
                if (notch >= 0)
                {
                    main.Notch(i, at[i], notch);
                }
            }
        }

        CellId storeyId = default, stairwellId = default;
        if (plan.Storey)
        {
            int u = main.Storey(at[0], plan.OwnFrames);
            storeyId = main.Id(u);
            main.Link(0, u, main.Corner(at[0]) + new Vector3(plan.Width / 2, plan.Depth / 2, EstatePlan.Floor + EstatePlan.Height), -Vector3.UnitZ);
            if (plan.Stairwell)
            {
                int s = main.Stairwell(at[0], plan.OwnFrames);
                stairwellId = main.Id(s);
                var face = main.Corner(at[0]) + new Vector3(plan.Width * EstateDraft.StairwellFrom, plan.Depth / 2, 0);
                main.Link(0, s, face, -Vector3.UnitX);
                main.Link(u, s, face, -Vector3.UnitX);
            }
        }

        var unloaded = new List<CellId>();
        if (plan.UnloadedRoom > 0 && plan.UnloadedRoom < at.Length && !doors.Any(d => d.Room == plan.UnloadedRoom))
        {
            unloaded.Add(main.Id(plan.UnloadedRoom));
        }

        var cells = main.Cells(plan.SeeDepth).Where(c => !unloaded.Contains(c.Id)).ToList();
        var buildings = new List<SceneBuilding> { main.Building(plan.Frame.Origin) };
        var used3 = new List<LandblockId> { plan.Block };
        for (int k = 1; k <= Math.Clamp(plan.ExtraBuildings, 0, 3); k++)
        {
            var (ox, oy) = k switch { 1 => (45.0, 0.0), 2 => (0.0, 45.0), _ => (45.0, 45.0) };
            double wx = plan.WorldX + ox, wy = plan.WorldY + oy;
            var block = EstatePlan.BlockOf(wx, wy);
            var origin = new Vector3((float)(wx - (192.0 * block.X)), (float)(wy - (192.0 * block.Y)), 0);
            var extra = new EstateDraft(block, (ushort)(0x100 + (0x10 * k)), new Frame(origin, Quaternion.Identity), 6, 6, plan.Flips >> k);
            extra.Room((0, 0), false, 0);
            extra.Door(0, extra.WallPoint((0, 0), GridSide.South), -Vector3.UnitY, true);
            cells.AddRange(extra.Cells(0));
            buildings.Add(extra.Building(origin));
            used3.Add(block);
        }

        var model = new EstateModel(new Scene([], [], []), plan, doorList, [.. at.Select(p => (main.Corner(p) + new Vector3(plan.Width / 2, plan.Depth / 2, 0)) with { Z = 0 })], at)
        {
            StoreyId = storeyId,
            StairwellId = stairwellId,
        };
        if (plan.Lead > 0 && doorList.Count > 0)
        {
            var (leadCells, centres, start) = Lead(plan, model.ToBlock(doorList[Entry(plan, doorList.Count)].Point));
            cells.AddRange(leadCells);
            used3.Add(start.Landblock);
            model = model with { LeadCentres = centres, LeadStart = start };
        }

        var blocks = used3.SelectMany(Around).Distinct().ToList();
        return model with { Scene = new Scene(blocks, buildings, cells) { UnloadedCells = unloaded } };
    }

    /// <summary>Returns the entry door index.</summary>
    /// <param name="plan">The plan.</param>
    /// <param name="doors">How many doors there are.</param>
    /// <returns>The index.</returns>
    public static int Entry(EstatePlan plan, int doors) => doors == 0 ? 0 : Math.Abs(plan.EntryDoor) % doors;

    /// <summary>Returns the exit door index: another door than the entry when there are two or more.</summary>
    /// <param name="plan">The plan.</param>
    /// <param name="doors">How many doors there are.</param>
    /// <returns>The index.</returns>
    public static int Exit(EstatePlan plan, int doors) => doors < 2 ? Entry(plan, doors) : (Entry(plan, doors) + 1 + (Math.Abs(plan.ExitDoor) % (doors - 1))) % doors;

    /// <summary>Returns a side's outward unit normal in the building frame.</summary>
    /// <param name="s">The side.</param>
    /// <returns>The normal.</returns>
    public static Vector3 Outward(GridSide s) => s switch
    {
        GridSide.South => -Vector3.UnitY,
        GridSide.North => Vector3.UnitY,
        GridSide.West => -Vector3.UnitX,
        _ => Vector3.UnitX,
    };

    // Doors: rooms in order (the unloaded room skipped), each its first free wall; with a lead-in, door 0 is room 0's west wall.
    private static List<(int Room, GridSide Side)> ChooseDoors(EstatePlan plan, (int X, int Y)[] at)
    {
        var doors = new List<(int, GridSide)>();
        for (int i = 0; i < at.Length && doors.Count < Math.Clamp(plan.Doors, 1, 4); i++)
        {
            if (i == plan.UnloadedRoom && i > 0)
            {
                continue;
            }

            var free = EstateGrid.FreeSides(at, i).ToList();
            if (i == 0 && plan.Lead > 0)
            {
                free = [GridSide.West];
            }

            if (free.Count > 0)
            {
                doors.Add((i, free[0]));
            }
        }

        return doors;
    }

    // A dungeon chain in the block west of the estate, ending in an exit 6 m west of the entry door (block-frame point
    // `door`); its cells' frames lie past x = 192 of their own block, in the estate block's area.
    private static (List<SceneCell> Cells, List<Vector3> Centres, CellId Start) Lead(EstatePlan plan, Vector3 door)
    {
        const float length = 6f, width = 4f;
        int n = Math.Clamp(plan.Lead, 1, 3);
        var block = new LandblockId((byte)(plan.Block.X - 1), plan.Block.Y);
        var ids = Enumerable.Range(0, n).Select(i => block.BlockCell.WithLow((ushort)(0x180 + i))).ToArray();
        float exitX = door.X + 192 - 6, y0 = door.Y - (width / 2);
        var cells = new List<SceneCell>();
        var centres = new List<Vector3>();
        for (int i = 0; i < n; i++)
        {
            var origin = new Vector3(exitX - ((n - i) * length), y0, 0);
            var portals = new List<ScenePortal>();
            if (i > 0)
            {
                portals.Add(new ScenePortal(new CellPlane(Vector3.UnitX, 0), ids[i - 1].Low, PortalSide: false, (ushort)(i - 1 == 0 ? 0 : 1)));
            }

            portals.Add(i < n - 1
                ? new ScenePortal(new CellPlane(Vector3.UnitX, -length), ids[i + 1].Low, PortalSide: true, 0)
                : new ScenePortal(new CellPlane(Vector3.UnitX, -length), CellPortal.Outside, PortalSide: true));
            var box = ScenePiece.FromBox(new Vector3(0, 0, EstatePlan.Floor), new Vector3(length, width, EstatePlan.Floor + EstatePlan.Height));
            cells.Add(new SceneCell(ids[i], origin, Quaternion.Identity, [box], portals, [.. ids.Where(x => x != ids[i])]));
            centres.Add(origin + new Vector3(length / 2, width / 2, 0));
        }

        return (cells, centres, ids[0]);
    }

    private static IEnumerable<LandblockId> Around(LandblockId home)
    {
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                int x = home.X + dx, y = home.Y + dy;
                if (x >= 0 && y >= 0 && x <= LandDefs.MaxBlockByte && y <= LandDefs.MaxBlockByte)
                {
                    yield return new LandblockId((byte)x, (byte)y);
                }
            }
        }
    }
}
