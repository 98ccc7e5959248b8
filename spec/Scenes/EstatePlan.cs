using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>How an estate's rooms sit on its grid: a row, a tree branching at room 1, or a ring closing loops.</summary>
public enum EstateLayout
{
    /// <summary>Rooms (i, 0) in a row.</summary>
    Row,

    /// <summary>Room 1 is a hub: rooms 0, 2, 3, 4 hang off it (a branch from 4 rooms on).</summary>
    Branch,

    /// <summary>A 2 × 2 ring (a loop from 4 rooms on), then a second ring east of it.</summary>
    Ring,
}

/// <summary>
/// An estate: a building of 1–6 grid rooms (a room graph that may branch or loop), 1–4 doors (building portals, some
/// carrying the invalid marker), each cell in its own frame (origin and quarter turns per cell, the building yawed and
/// tilted), shared walls that are portal pairs or sealed, optionally a storey above room 0 with a stairwell overlapping both, L-shaped rooms (two pieces), a thin
/// vestibule at the entry door, an unloaded room, up to three further buildings nearby, and a dungeon lead-in in the
/// next block west whose cells reach into the estate's block. Placed by the world position of its origin.
/// </summary>
/// <param name="WorldX">Origin, world x (metres).</param>
/// <param name="WorldY">Origin, world y.</param>
/// <param name="Layout">The room graph.</param>
/// <param name="Rooms">1 to 6.</param>
/// <param name="Width">Grid room width along x.</param>
/// <param name="Depth">Grid room depth along y.</param>
/// <param name="Doors">1 to 4 (capped by the rooms with a free wall).</param>
/// <param name="InvalidDoors">Bit j: door j's building portal carries the invalid marker (never the entry door).</param>
/// <param name="Yaw">Building yaw, radians.</param>
/// <param name="Tilt">Small tilt about x and y, radians (0 = upright).</param>
/// <param name="CellTurns">Two bits per cell: its quarter turns about z relative to the building; with <paramref name="OwnFrames"/>.</param>
/// <param name="OwnFrames">Whether each cell has its own frame origin and turn (else all share the building's frame).</param>
/// <param name="Flips">Bit i flips portal i's plane (PortalSide false instead of true).</param>
public sealed record EstatePlan(double WorldX, double WorldY, EstateLayout Layout, int Rooms, float Width, float Depth, int Doors, int InvalidDoors, float Yaw, Vector2 Tilt, int CellTurns, bool OwnFrames, int Flips)
{
    /// <summary>Room height, metres (floor 0.5 m below the walk's plane, so a small tilt keeps the body inside).</summary>
    public const float Height = 3.5f;

    /// <summary>Floor height in the building frame.</summary>
    public const float Floor = -0.5f;

    /// <summary>Thickness of a vestibule (a thin doorway cell), metres.</summary>
    public const float VestibuleDepth = 0.25f;

    /// <summary>Gets a value indicating whether room 0 has a storey above it.</summary>
    public bool Storey { get; init; }

    /// <summary>Gets a value indicating whether a stairwell cell overlaps room 0's east half and the storey (needs <see cref="Storey"/>).</summary>
    public bool Stairwell { get; init; }

    /// <summary>Gets bit i: room i is L-shaped (a second piece) when it has a free wall left for the notch.</summary>
    public int LShapes { get; init; }

    /// <summary>Gets a value indicating whether the entry door opens into a thin vestibule cell (two portals within 0.25 m).</summary>
    public bool Vestibule { get; init; }

    /// <summary>
    /// Gets bit k: the k-th shared wall (<see cref="EstateGrid.Links"/> order) is sealed — no portal pair, so the rooms
    /// on either side meet only through their own doors (a duplex).
    /// </summary>
    public int SealedWalls { get; init; }

    /// <summary>Gets the room that is declared but not loaded (a load hint in the middle of the graph), or −1.</summary>
    public int UnloadedRoom { get; init; } = -1;

    /// <summary>Gets how far a cell sees along portal links: 1 (neighbours), 2, or 0 (every cell of its building).</summary>
    public int SeeDepth { get; init; }

    /// <summary>Gets further one-room buildings nearby (0 to 3): 45 m east, north and north-east of the origin.</summary>
    public int ExtraBuildings { get; init; }

    /// <summary>Gets the number of dungeon cells leading to the entry door from the block to the west (0 = none).</summary>
    public int Lead { get; init; }

    /// <summary>Gets the entry door index.</summary>
    public int EntryDoor { get; init; }

    /// <summary>Gets the exit door index.</summary>
    public int ExitDoor { get; init; }

    /// <summary>Gets the block containing the origin.</summary>
    public LandblockId Block => BlockOf(WorldX, WorldY);

    /// <summary>Gets the origin in <see cref="Block"/>'s frame.</summary>
    public Vector3 Origin => new((float)(WorldX - (192.0 * Block.X)), (float)(WorldY - (192.0 * Block.Y)), 0f);

    /// <summary>Gets the building rotation: yaw about z after the tilt about x and y.</summary>
    public Quaternion Rotation => Quaternion.Concatenate(
        Quaternion.Concatenate(Quaternion.CreateFromAxisAngle(Vector3.UnitX, Tilt.X), Quaternion.CreateFromAxisAngle(Vector3.UnitY, Tilt.Y)),
        Quaternion.CreateFromAxisAngle(Vector3.UnitZ, Yaw));

    /// <summary>Gets the building frame in <see cref="Block"/>'s frame.</summary>
    public Frame Frame => new(Origin, Rotation);

    /// <summary>Returns the block containing a world point.</summary>
    /// <param name="x">World x.</param>
    /// <param name="y">World y.</param>
    /// <returns>The block.</returns>
    public static LandblockId BlockOf(double x, double y) => new((byte)Math.Floor(x / 192), (byte)Math.Floor(y / 192));
}
