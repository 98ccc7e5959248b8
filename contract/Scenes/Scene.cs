using System.Numerics;
using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>A convex piece of a cell: an axis-aligned box or a list of inner half-spaces, in the cell's local frame.</summary>
/// <param name="Box">The box, or null when <paramref name="Planes"/> is given.</param>
/// <param name="Planes">Inner half-spaces (N·p + D ≥ 0 inside), or null when <paramref name="Box"/> is given.</param>
public sealed record ScenePiece(Box? Box, IReadOnlyList<CellPlane>? Planes)
{
    // The core piece, built once (issue 26: a ConditionalWeakTable entry per piece cost every collection a dependent
    // handle, on both ends of the wire). Not part of the value: equality, hashing and `with` see Box and Planes only.
    private ConvexPiece? convex;

    // `with` copies the value only: the copy's Box or Planes may differ, so its core piece is built anew.
    private ScenePiece(ScenePiece original)
    {
        Box = original.Box;
        Planes = original.Planes;
    }

    /// <summary>Returns a box piece.</summary>
    /// <param name="min">Minimum corner.</param>
    /// <param name="max">Maximum corner.</param>
    /// <returns>The piece.</returns>
    public static ScenePiece FromBox(Vector3 min, Vector3 max) => new(new Box(min, max), null);

    /// <summary>Returns a plane piece whose core piece a reader has already built while checking the planes.</summary>
    /// <param name="planes">The planes.</param>
    /// <param name="built"><c>new ConvexPiece(planes)</c>, built by the caller: <see cref="ToConvex"/> returns it instead of building it again.</param>
    /// <returns>The piece.</returns>
    /// <remarks>Issue 26: a scene read from dat records built each piece three times (the reader's check, the scene
    /// rules' check, the query scene).</remarks>
    public static ScenePiece OfChecked(IReadOnlyList<CellPlane> planes, ConvexPiece built) => new(null, planes) { convex = built };

    /// <summary>Returns a box piece whose core piece a reader has already built from the box's six planes.</summary>
    /// <param name="min">Minimum corner.</param>
    /// <param name="max">Maximum corner.</param>
    /// <param name="built"><c>ConvexPiece.FromBox(min, max)</c>, or the piece of the same six planes in the same order, built by the caller.</param>
    /// <returns>The piece.</returns>
    public static ScenePiece OfCheckedBox(Vector3 min, Vector3 max, ConvexPiece built) => new(new Box(min, max), null) { convex = built };

    /// <summary>Builds the core piece (once per piece).</summary>
    /// <returns>The convex piece.</returns>
    public ConvexPiece ToConvex() => convex ??= Box is { } b ? ConvexPiece.FromBox(b.Min, b.Max) : new ConvexPiece(Planes!);

    /// <inheritdoc/>
    public bool Equals(ScenePiece? other) =>
        other is not null && EqualityComparer<Box?>.Default.Equals(Box, other.Box) && EqualityComparer<IReadOnlyList<CellPlane>?>.Default.Equals(Planes, other.Planes);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(Box, Planes);
}

/// <summary>A portal of a scene cell: plane (cell-local), the cell behind (low word, 0xFFFF outside), PortalSide, and the other cell's portal index.</summary>
/// <param name="Plane">The portal plane in the owning cell's local frame.</param>
/// <param name="Other">Low word of the cell behind, or 0xFFFF for outside.</param>
/// <param name="PortalSide">True when the owning cell is on the plane's negative side (facts §5.4).</param>
/// <param name="OtherPortal">The other cell's portal index (0xFFFF = none).</param>
public sealed record ScenePortal(CellPlane Plane, ushort Other, bool PortalSide, ushort OtherPortal = 0xFFFF)
{
    /// <summary>
    /// Gets the portal's polygon, vertices in the cell's frame in winding order, or null when the scene gives the plane
    /// alone (optional: a port that takes planes ignores it). When given, the plane derived from it (the normalised sum
    /// of fan cross products, as the dat reader derives it) is <see cref="Plane"/> (docs/indoor.md, "Scene files").
    /// </summary>
    public IReadOnlyList<System.Numerics.Vector3>? Polygon { get; init; }

    /// <summary>Gets a value indicating whether the portal leads outside.</summary>
    public bool IsExit => Other == CellPortal.Outside;
}

/// <summary>An env cell of a scene.</summary>
/// <param name="Id">Full env cell id.</param>
/// <param name="Origin">Frame origin in the cell's block frame.</param>
/// <param name="Rotation">Unit quaternion.</param>
/// <param name="Pieces">Convex pieces (a union).</param>
/// <param name="Portals">Portals in dat order.</param>
/// <param name="Visible">Full ids of the cells visible from this one.</param>
public sealed record SceneCell(CellId Id, Vector3 Origin, Quaternion Rotation, IReadOnlyList<ScenePiece> Pieces, IReadOnlyList<ScenePortal> Portals, IReadOnlyList<CellId> Visible);

/// <summary>A building portal: the env cell behind it (low word, same block) and that cell's portal index.</summary>
/// <param name="Cell">Env cell low word.</param>
/// <param name="Portal">Index into that cell's portal list (0xFFFF = none).</param>
public sealed record SceneBldPortal(ushort Cell, ushort Portal);

/// <summary>A building of a scene.</summary>
/// <param name="Block">The block it is declared in.</param>
/// <param name="Origin">Its origin in that block's frame (decides the owning land cell, facts §5.3).</param>
/// <param name="Portals">Building portals.</param>
public sealed record SceneBuilding(LandblockId Block, Vector3 Origin, IReadOnlyList<SceneBldPortal> Portals);

/// <summary>
/// A scene: only what a test needs. Loaded landblocks (any other block is unloaded), declared-but-unloaded blocks and
/// env cells (portals may point at them: load hints), buildings and env cells. Serialised by <c>SceneJson</c> (AcPhys.Formats).
/// </summary>
/// <param name="Blocks">Loaded landblocks.</param>
/// <param name="Buildings">Buildings.</param>
/// <param name="Cells">Loaded env cells.</param>
public sealed record Scene(IReadOnlyList<LandblockId> Blocks, IReadOnlyList<SceneBuilding> Buildings, IReadOnlyList<SceneCell> Cells)
{
    /// <summary>Gets the declared but unloaded landblocks.</summary>
    public IReadOnlyList<LandblockId> UnloadedBlocks { get; init; } = [];

    /// <summary>Gets env cells that exist but are not loaded (a portal into one yields a load hint).</summary>
    public IReadOnlyList<CellId> UnloadedCells { get; init; } = [];

    /// <summary>Gets the number of portals (cell and building), for reports of shrunk sizes.</summary>
    public int PortalCount => Cells.Sum(c => c.Portals.Count) + Buildings.Sum(b => b.Portals.Count);

    /// <summary>Returns the scene moved by whole landblocks: ids change, block-frame coordinates do not.</summary>
    /// <param name="dx">Block columns.</param>
    /// <param name="dy">Block rows.</param>
    /// <returns>The moved scene.</returns>
    public Scene Translated(int dx, int dy)
    {
        LandblockId B(LandblockId b) => new((byte)(b.X + dx), (byte)(b.Y + dy));
        CellId C(CellId c) => new((byte)(c.BlockX + dx), (byte)(c.BlockY + dy), c.Low);
        return new Scene(
            [.. Blocks.Select(B)],
            [.. Buildings.Select(b => b with { Block = B(b.Block) })],
            [.. Cells.Select(c => c with { Id = C(c.Id), Visible = [.. c.Visible.Select(C)] })])
        {
            UnloadedBlocks = [.. UnloadedBlocks.Select(B)],
            UnloadedCells = [.. UnloadedCells.Select(C)],
        };
    }

    /// <summary>Summarises the scene on one line.</summary>
    /// <returns>The text.</returns>
    public override string ToString() =>
        $"scene blocks [{string.Join(", ", Blocks)}] unloaded [{string.Join(", ", UnloadedBlocks)}], {Buildings.Count} building(s), {Cells.Count} cell(s) [{string.Join(", ", Cells.Select(c => c.Id))}], {PortalCount} portal(s)";
}
