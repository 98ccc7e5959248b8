using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>
/// A cottage: 1–4 box rooms in a row along its local +x, a front door (an exit) in room 0's south wall, doors between
/// neighbouring rooms, optionally a back door in the last room and a storey above room 0. Placed by its world origin
/// (metres from the map's south-west corner) and yaw; the building belongs to the block containing the origin.
/// </summary>
/// <param name="WorldX">Origin, world x.</param>
/// <param name="WorldY">Origin, world y.</param>
/// <param name="Yaw">Rotation about +z, radians.</param>
/// <param name="Rooms">1 to 4.</param>
/// <param name="Width">Room width along x, metres.</param>
/// <param name="Depth">Room depth along y, metres.</param>
/// <param name="Flips">Bit i flips portal i's plane (PortalSide false instead of true), to exercise both flags.</param>
/// <param name="BackDoor">Whether the last room has an exit in its north wall.</param>
/// <param name="Storey">Whether a storey sits above room 0 (a ceiling portal).</param>
/// <param name="LoadNeighbours">Whether the 8 blocks around the cottage's block are loaded (else declared unloaded).</param>
public sealed record CottagePlan(double WorldX, double WorldY, float Yaw, int Rooms, float Width, float Depth, int Flips, bool BackDoor, bool Storey, bool LoadNeighbours = true)
{
    /// <summary>Room height, metres.</summary>
    public const float Height = 3f;

    /// <summary>The sealed closet's width along x, metres (it lies west of room 0).</summary>
    public const float ClosetWidth = 2.5f;

    /// <summary>
    /// Gets a value indicating whether a sealed closet stands west of room 0: an env cell with no cell portals, entered
    /// only by a building portal of its own and listed in every room's VisibleCells. Retail's point_in_cell refuses a cell
    /// without portals (facts §5.5, §7 #13), so a centre inside it is never in it; ACE's is.
    /// </summary>
    public bool Closet { get; init; }

    /// <summary>Gets the closet's cell index (after the rooms and the storey).</summary>
    public int ClosetIndex => Rooms + (Storey ? 1 : 0);

    /// <summary>Gets the block containing the origin.</summary>
    public LandblockId Block => new((byte)Math.Floor(WorldX / 192), (byte)Math.Floor(WorldY / 192));

    /// <summary>Gets the origin in <see cref="Block"/>'s frame.</summary>
    public Vector3 Origin => new((float)(WorldX - (192.0 * Block.X)), (float)(WorldY - (192.0 * Block.Y)), 0f);

    /// <summary>Gets the rotation.</summary>
    public Quaternion Rotation => Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Yaw);

    /// <summary>Returns room i's cell id.</summary>
    /// <param name="i">Room index; <see cref="Rooms"/> is the storey.</param>
    /// <returns>The id.</returns>
    public CellId RoomId(int i) => Block.BlockCell.WithLow((ushort)(0x100 + i));

    /// <summary>Maps a cottage-local point to the block frame.</summary>
    /// <param name="local">Local point.</param>
    /// <returns>Block-frame point.</returns>
    public Vector3 ToBlock(Vector3 local) => new Frame(Origin, Rotation).LocalToGlobal(local);
}

/// <summary>A dungeon chain: box cells in a row along +x from a world origin, no building, an exit at the far end; the tail may be unloaded.</summary>
/// <param name="WorldX">Origin, world x.</param>
/// <param name="WorldY">Origin, world y.</param>
/// <param name="Cells">Number of cells (2 to 5).</param>
/// <param name="Length">Cell length along x.</param>
/// <param name="Unloaded">How many cells at the tail are declared but not loaded (load hints).</param>
/// <param name="Flips">Bit i flips portal i's plane.</param>
public sealed record DungeonPlan(double WorldX, double WorldY, int Cells, float Length, int Unloaded, int Flips)
{
    /// <summary>Gets the block containing the origin.</summary>
    public LandblockId Block => new((byte)Math.Floor(WorldX / 192), (byte)Math.Floor(WorldY / 192));

    /// <summary>Gets the origin in the block's frame.</summary>
    public Vector3 Origin => new((float)(WorldX - (192.0 * Block.X)), (float)(WorldY - (192.0 * Block.Y)), 0f);
}

/// <summary>Deterministic scene builders for tests, generators and the corpus.</summary>
public static class SceneKit
{
    /// <summary>Room / cell width across a dungeon, metres.</summary>
    public const float DungeonWidth = 4f;

    /// <summary>Builds a cottage scene.</summary>
    /// <param name="plan">The plan.</param>
    /// <returns>The scene.</returns>
    public static Scene Cottage(CottagePlan plan)
    {
        int n = plan.Rooms;
        float w = plan.Width, d = plan.Depth, h = CottagePlan.Height;
        var portals = new List<ScenePortal>[n + (plan.Storey ? 1 : 0)];
        for (int i = 0; i < portals.Length; i++)
        {
            portals[i] = [];
        }

        int flipIndex = 0;
        bool Flip() => ((plan.Flips >> (flipIndex++ % 31)) & 1) != 0;

        // A portal whose owning cell is on the side "inside" points toward; the plane is flipped on request.
        void Add(int cell, Vector3 inward, Vector3 point, ushort other)
        {
            bool flip = Flip();
            var normal = flip ? inward : -inward;
            portals[cell].Add(new ScenePortal(CellPlane.Through(normal, point), other, PortalSide: !flip));
        }

        Add(0, Vector3.UnitY, new Vector3(w / 2, 0, 0), CellPortal.Outside);
        for (int i = 0; i < n - 1; i++)
        {
            var wall = new Vector3((i + 1) * w, d / 2, 0);
            Add(i, -Vector3.UnitX, wall, (ushort)(0x100 + i + 1));
            Add(i + 1, Vector3.UnitX, wall, (ushort)(0x100 + i));
        }

        if (plan.BackDoor)
        {
            Add(n - 1, -Vector3.UnitY, new Vector3((n - 0.5f) * w, d, 0), CellPortal.Outside);
        }

        if (plan.Storey)
        {
            var ceiling = new Vector3(w / 2, d / 2, h);
            Add(0, -Vector3.UnitZ, ceiling, (ushort)(0x100 + n));
            Add(n, Vector3.UnitZ, ceiling, 0x100);
        }

        var ids = Enumerable.Range(0, portals.Length + (plan.Closet ? 1 : 0)).Select(plan.RoomId).ToArray();
        var cells = new List<SceneCell>();
        for (int i = 0; i < portals.Length; i++)
        {
            var box = i < n
                ? ScenePiece.FromBox(new Vector3(i * w, 0, 0), new Vector3((i + 1) * w, d, h))
                : ScenePiece.FromBox(new Vector3(0, 0, h), new Vector3(w, d, 2 * h));
            cells.Add(new SceneCell(ids[i], plan.Origin, plan.Rotation, [box], LinkBack(portals, i, ids), [.. ids.Where(x => x != ids[i])]));
        }

        var bld = new List<SceneBldPortal> { new(0x100, 0) };
        if (plan.BackDoor)
        {
            bld.Add(new SceneBldPortal((ushort)(0x100 + n - 1), (ushort)portals[n - 1].FindIndex(p => p.IsExit)));
        }

        if (plan.Closet)
        {
            // No cell portals at all: the building portal is its only way in (its portal index names no portal of the
            // closet; only 0xFFFF would stop the entry test, facts §5.3). Seen by every room through VisibleCells.
            var closet = ids[plan.ClosetIndex];
            var box = ScenePiece.FromBox(new Vector3(-CottagePlan.ClosetWidth, 0, 0), new Vector3(0, MathF.Min(d, 4f), h));
            cells.Add(new SceneCell(closet, plan.Origin, plan.Rotation, [box], [], [.. ids.Where(x => x != closet)]));
            bld.Add(new SceneBldPortal(closet.Low, 0));
        }

        var (loaded, unloaded) = Blocks(plan.Block, plan.LoadNeighbours);
        return new Scene(loaded, [new SceneBuilding(plan.Block, plan.Origin, bld)], cells) { UnloadedBlocks = unloaded };
    }

    /// <summary>Builds a dungeon chain scene (its block and neighbours loaded).</summary>
    /// <param name="plan">The plan.</param>
    /// <returns>The scene.</returns>
    public static Scene Dungeon(DungeonPlan plan)
    {
        int n = plan.Cells;
        var block = plan.Block.BlockCell;
        var portals = new List<ScenePortal>[n];
        for (int i = 0; i < n; i++)
        {
            portals[i] = [];
        }

        int flipIndex = 0;
        void Add(int cell, Vector3 inward, Vector3 point, ushort other)
        {
            bool flip = ((plan.Flips >> (flipIndex++ % 31)) & 1) != 0;
            portals[cell].Add(new ScenePortal(CellPlane.Through(flip ? inward : -inward, point), other, PortalSide: !flip));
        }

        for (int i = 0; i < n - 1; i++)
        {
            var wall = new Vector3((i + 1) * plan.Length, DungeonWidth / 2, 0);
            Add(i, -Vector3.UnitX, wall, (ushort)(0x100 + i + 1));
            Add(i + 1, Vector3.UnitX, wall, (ushort)(0x100 + i));
        }

        Add(n - 1, -Vector3.UnitX, new Vector3(n * plan.Length, DungeonWidth / 2, 0), CellPortal.Outside);
        var ids = Enumerable.Range(0, n).Select(i => block.WithLow((ushort)(0x100 + i))).ToArray();
        int loadedCount = Math.Max(1, n - plan.Unloaded);
        var cells = new List<SceneCell>();
        for (int i = 0; i < loadedCount; i++)
        {
            var box = ScenePiece.FromBox(new Vector3(i * plan.Length, 0, 0), new Vector3((i + 1) * plan.Length, DungeonWidth, CottagePlan.Height));
            cells.Add(new SceneCell(ids[i], plan.Origin, Quaternion.Identity, [box], LinkBack(portals, i, ids), [.. ids.Where(x => x != ids[i])]));
        }

        var (loaded, unloadedBlocks) = Blocks(plan.Block, true);
        return new Scene(loaded, [], cells) { UnloadedBlocks = unloadedBlocks, UnloadedCells = [.. ids.Skip(loadedCount)] };
    }

    private static List<ScenePortal> LinkBack(List<ScenePortal>[] portals, int i, CellId[] ids) =>
        [.. portals[i].Select(p => p.IsExit ? p : p with { OtherPortal = (ushort)Math.Max(0, portals[p.Other - 0x100].FindIndex(q => q.Other == ids[i].Low)) })];

    private static (List<LandblockId> Loaded, List<LandblockId> Unloaded) Blocks(LandblockId home, bool neighbours)
    {
        var loaded = new List<LandblockId> { home };
        var unloaded = new List<LandblockId>();
        for (int dx = -1; dx <= 1; dx++)
        {
            for (int dy = -1; dy <= 1; dy++)
            {
                int x = home.X + dx, y = home.Y + dy;
                if ((dx, dy) == (0, 0) || x < 0 || y < 0 || x > LandDefs.MaxBlockByte || y > LandDefs.MaxBlockByte)
                {
                    continue;
                }

                (neighbours ? loaded : unloaded).Add(new LandblockId((byte)x, (byte)y));
            }
        }

        return (loaded, unloaded);
    }
}
