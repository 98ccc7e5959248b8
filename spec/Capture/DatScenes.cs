using AcPhys.Contract;
using AcPhys.Core;
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
    private readonly Dictionary<LandblockId, bool> buildings = [];

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

    /// <summary>Tests whether a block may hold a building (its LandblockInfo is in the cell database): an outdoor frame there may enter one.</summary>
    /// <param name="block">The block.</param>
    /// <returns>True when its LandblockInfo record exists.</returns>
    public bool MayHoldBuildings(LandblockId block)
    {
        if (!buildings.TryGetValue(block, out bool has))
        {
            has = block.IsOnMap && world.Cell.Contains(SceneExtraction.LandblockRecordId(block) - 1);
            buildings[block] = has;
        }

        return has;
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
}
