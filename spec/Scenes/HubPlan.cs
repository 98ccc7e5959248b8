using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Spec.Scenes;

/// <summary>
/// A hub: four small box cells (quadrants) meeting at one corner — Q0 south-west, Q1 south-east, Q2 north-east, Q3
/// north-west — with portal pairs on the four inner walls (some sealed), exits on some outer walls, each cell's portals
/// in a shuffled dat order and each cell's VisibleCells missing some cells, portal neighbours included. A body near the
/// meeting corner reaches every quadrant and, through a straddled exit, the land: many candidates, several of which
/// the indoor visibility filter removes from the middle of the array (facts §4 step 5, §5.9), and portal neighbours
/// that are not in the walked cell's VisibleCells (facts §5.1, §7 #10). Optionally a low storey of four more quadrants
/// (U0–U3 above Q0–Q3, ceiling portals between them) that a two-sphere body's upper sphere reaches: cells found late
/// in the closure, behind the land cells. No building: the walk stays in Q0.
/// </summary>
/// <param name="WorldX">The meeting corner, world x (metres).</param>
/// <param name="WorldY">The meeting corner, world y.</param>
/// <param name="SizeX">Quadrant width along x, metres.</param>
/// <param name="SizeY">Quadrant depth along y, metres.</param>
/// <param name="Sealed">Bit k: inner wall k (Q0–Q1, Q1–Q2, Q2–Q3, Q3–Q0) has no portal pair.</param>
/// <param name="Exits">Bit 2i, 2i+1: quadrant i's first and second outer wall is an exit.</param>
/// <param name="Blind">Bit 4i + j: quadrant i does not list quadrant j in its VisibleCells.</param>
/// <param name="Order">Seeds each cell's dat order of portals.</param>
/// <param name="Flips">Bit i flips portal i's plane (PortalSide false instead of true).</param>
public sealed record HubPlan(double WorldX, double WorldY, float SizeX, float SizeY, int Sealed, int Exits, int Blind, int Order, int Flips)
{
    /// <summary>Gets the ceiling height of the lower quadrants (the upper ones are as high again), metres.</summary>
    public float Height { get; init; } = 3f;

    /// <summary>Gets a value indicating whether the upper quadrants exist.</summary>
    public bool Storey { get; init; }

    /// <summary>Gets bit 4i + j: lower quadrant i does not list upper quadrant j in its VisibleCells.</summary>
    public int BlindUp { get; init; }

    /// <summary>Gets how far inside Q0 the walk's turning point stays from both inner walls, metres.</summary>
    public float Inset { get; init; } = 0.25f;

    /// <summary>Gets the block containing the meeting corner.</summary>
    public LandblockId Block => new((byte)Math.Floor(WorldX / 192), (byte)Math.Floor(WorldY / 192));

    /// <summary>Gets the meeting corner in <see cref="Block"/>'s frame (every cell's frame origin).</summary>
    public Vector3 Corner => new((float)(WorldX - (192.0 * Block.X)), (float)(WorldY - (192.0 * Block.Y)), 0f);

    /// <summary>Returns quadrant i's cell id.</summary>
    /// <param name="i">0 to 3.</param>
    /// <returns>The id.</returns>
    public CellId QuadrantId(int i) => Block.BlockCell.WithLow((ushort)(0x100 + i));

    /// <summary>Returns upper quadrant i's cell id.</summary>
    /// <param name="i">0 to 3.</param>
    /// <returns>The id.</returns>
    public CellId UpperId(int i) => Block.BlockCell.WithLow((ushort)(0x104 + i));

    /// <summary>Returns whether the portal pair between two quadrants exists (their shared wall is not sealed).</summary>
    /// <param name="i">A quadrant.</param>
    /// <param name="j">Another quadrant.</param>
    /// <returns>True when linked.</returns>
    public bool Linked(int i, int j) => ((i + 1) % 4 == j || (j + 1) % 4 == i) && ((Sealed >> ((i + 1) % 4 == j ? i : j)) & 1) == 0;

    /// <summary>Returns whether quadrant i lists quadrant j in its VisibleCells.</summary>
    /// <param name="i">The seeing quadrant.</param>
    /// <param name="j">The seen quadrant.</param>
    /// <returns>True when seen.</returns>
    public bool Sees(int i, int j) => i != j && ((Blind >> ((4 * i) + j)) & 1) == 0;

    /// <summary>Returns whether lower quadrant i lists upper quadrant j in its VisibleCells (with a storey).</summary>
    /// <param name="i">The seeing lower quadrant.</param>
    /// <param name="j">The seen upper quadrant.</param>
    /// <returns>True when seen.</returns>
    public bool SeesUp(int i, int j) => Storey && ((BlindUp >> ((4 * i) + j)) & 1) == 0;

    /// <summary>Gets a value indicating whether Q0 (the walked cell) misses a linked neighbour in its VisibleCells.</summary>
    public bool BlindNeighbour => Enumerable.Range(1, 3).Any(j => Linked(0, j) && !Sees(0, j)) || (Storey && !SeesUp(0, 0));
}
