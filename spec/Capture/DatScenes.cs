using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Dat;
using AcPhys.Formats.Dat.Container;

namespace AcPhys.Spec.Capture;

/// <summary>One landblock's scene from the user's dat files, built once: the scene, its core scene and its cells' faces.</summary>
/// <param name="Scene">The scene (the whole block and its neighbours, as <c>scene from-dat --landblock</c> extracts it).</param>
/// <param name="Built">Its core scene (BSP cells).</param>
/// <param name="Faces">Each env cell's BSP faces: its first piece's planes, the positive chain retail's queries follow (facts §5.7).</param>
internal sealed record BlockScene(Scene Scene, CellScene Built, IReadOnlyDictionary<CellId, IReadOnlyList<CellPlane>> Faces);

/// <summary>
/// The scenes the indoor judge asks the reference in, from the user's dat world: a landblock's scene is extracted as
/// <c>scene from-dat --landblock 0xAABB</c> extracts it (docs/dat-container.md, "Scenes from a dat world": the block, its
/// eight neighbours, every building, the env cells reachable from the doors and of the block) through the one record
/// reader, and kept (at most <see cref="MaxBlocks"/> blocks, then the cache starts again: constant memory on a long capture).
/// </summary>
internal sealed class DatScenes
{
    /// <summary>The most landblock scenes kept at once.</summary>
    public const int MaxBlocks = 32;

    private readonly DatWorld world;
    private readonly Dictionary<LandblockId, BlockScene?> scenes = [];
    private readonly Dictionary<LandblockId, HashSet<CellId>?> owners = [];

    /// <summary>Initializes a new instance of the <see cref="DatScenes"/> class.</summary>
    /// <param name="world">The dat world (the caller owns it).</param>
    public DatScenes(DatWorld world) => this.world = world;

    /// <summary>Gets how many landblock scenes were extracted.</summary>
    public int Extracted { get; private set; }

    /// <summary>Gets the landblocks whose scene the record reader refused, with the first reason.</summary>
    public Dictionary<LandblockId, string> Refused { get; } = [];

    /// <summary>Tests whether the cell database holds a block's Landblock record.</summary>
    /// <param name="block">The block.</param>
    /// <returns>True when it does.</returns>
    public bool HasBlock(LandblockId block) => world.Cell.Contains(SceneExtraction.LandblockRecordId(block));

    /// <summary>
    /// Tests whether a land cell may own a building (facts §5.3: a building is attached to the land cell its origin
    /// AdjustToOutside's to, in its own block): the cells its block's LandblockInfo attaches buildings to; every cell of a
    /// block whose LandblockInfo the record reader refuses (the scene judge then says why it cannot judge there).
    /// </summary>
    /// <param name="landCell">A land cell.</param>
    /// <returns>True when a building may be attached to it.</returns>
    public bool MayOwnBuilding(CellId landCell)
    {
        var block = landCell.Landblock;
        if (!owners.TryGetValue(block, out var cells))
        {
            cells = Owners(block);
            owners[block] = cells;
        }

        return cells is null || cells.Contains(landCell);
    }

    /// <summary>Tests whether the cell database holds an env cell's record.</summary>
    /// <param name="cell">The cell.</param>
    /// <returns>True when it does.</returns>
    public bool HasCell(CellId cell) => world.Cell.Contains(cell.Value);

    /// <summary>Returns a block's scene, or null when the cell database has no Landblock record of it or the reader refused it (<see cref="Refused"/>).</summary>
    /// <param name="block">The block.</param>
    /// <returns>The scene, or null.</returns>
    /// <exception cref="DatContainerException">A container is damaged (not a refused record: those are <see cref="Refused"/>).</exception>
    public BlockScene? Of(LandblockId block)
    {
        if (scenes.TryGetValue(block, out var known))
        {
            return known;
        }

        if (scenes.Count >= MaxBlocks)
        {
            scenes.Clear();
        }

        BlockScene? scene = null;
        if (HasBlock(block))
        {
            try
            {
                var got = SceneExtraction.Extract(world, new ScenePlace(block));
                scene = new BlockScene(got.Scene, SceneBuild.Build(got.Scene), got.Scene.Cells.ToDictionary(c => c.Id, c => c.Pieces[0].ToConvex().Planes));
                Extracted++;
            }
            catch (DatContainerException e) when (e.InnerException is AcPhys.Formats.InputFormatException)
            {
                Refused.TryAdd(block, e.Message);
            }
        }

        scenes[block] = scene;
        return scene;
    }

    // The land cells a block's buildings are attached to (empty: no LandblockInfo, or no building); null: unreadable.
    private HashSet<CellId>? Owners(LandblockId block)
    {
        uint id = SceneExtraction.LandblockRecordId(block) - 1;
        if (!block.IsOnMap || !world.Cell.Contains(id))
        {
            return [];
        }

        try
        {
            var info = LandblockInfoRecord.Read(world.Cell.Read(id), id);
            return [.. info.Buildings.Select(b => new Building(block, b.Origin, []).OwningCell()).Where(c => !c.IsNone)];
        }
        catch (AcPhys.Formats.InputFormatException)
        {
            return null;
        }
    }
}
