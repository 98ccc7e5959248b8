using System.Runtime.CompilerServices;
using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// A scene as the exact indoor invariants read it, cached per scene: the loaded env cells by id (<see cref="ExactCell"/>),
/// and each building by the land cell it is attached to (its origin AdjustToOutside'd, facts §5.3; discarded when that
/// falls in another block).
/// </summary>
internal sealed class ExactScene
{
    private static readonly ConditionalWeakTable<Scene, ExactScene> Cache = [];
    private readonly Dictionary<CellId, ExactCell> cells = [];
    private readonly Dictionary<CellId, SceneBuilding> attached = [];
    private readonly HashSet<LandblockId> blocks;

    private ExactScene(Scene scene)
    {
        Scene = scene;
        blocks = [.. scene.Blocks];
        foreach (var c in scene.Cells)
        {
            if (blocks.Contains(c.Id.Landblock))
            {
                cells.TryAdd(c.Id, new ExactCell(c));
            }
        }

        foreach (var b in scene.Buildings)
        {
            var owner = new Building(b.Block, b.Origin, []).OwningCell();
            if (!owner.IsNone)
            {
                attached.TryAdd(owner, b);
            }
        }
    }

    /// <summary>Gets the scene.</summary>
    public Scene Scene { get; }

    /// <summary>Returns the (cached) exact view of a scene.</summary>
    /// <param name="scene">The scene.</param>
    /// <returns>The view.</returns>
    public static ExactScene Of(Scene scene) => Cache.GetValue(scene, s => new ExactScene(s));

    /// <summary>Returns a loaded env cell, or null (not declared, or its block is not loaded).</summary>
    /// <param name="id">A cell id.</param>
    /// <returns>The cell.</returns>
    public ExactCell? Env(CellId id) => cells.GetValueOrDefault(id);

    /// <summary>Gets the loaded env cells.</summary>
    public IEnumerable<ExactCell> Envs => cells.Values;

    /// <summary>Tests whether a land cell's block is loaded.</summary>
    /// <param name="id">An id.</param>
    /// <returns>True for a land cell of a loaded block.</returns>
    public bool IsLoadedLand(CellId id) => id.IsLand && blocks.Contains(id.Landblock);

    /// <summary>Tests whether a block is loaded.</summary>
    /// <param name="block">The block.</param>
    /// <returns>True when loaded.</returns>
    public bool IsLoaded(LandblockId block) => blocks.Contains(block);

    /// <summary>Returns the building attached to a land cell of a loaded block, or null.</summary>
    /// <param name="land">A land cell.</param>
    /// <returns>The building.</returns>
    public SceneBuilding? BuildingOn(CellId land) => IsLoadedLand(land) ? attached.GetValueOrDefault(land) : null;

    /// <summary>Gets every attached building with its land cell.</summary>
    public IReadOnlyDictionary<CellId, SceneBuilding> Attached => attached;

    /// <summary>
    /// Tests whether find_cell_list runs its transit closure and pick for a position (facts §4 step 4: the position's
    /// own cell is loaded — a land cell of a loaded block, or a loaded env cell — and there are spheres).
    /// </summary>
    /// <param name="position">The position's cell id.</param>
    /// <param name="spheres">How many spheres.</param>
    /// <returns>True when the closure runs.</returns>
    public bool ClosureRuns(CellId position, int spheres) => spheres > 0 && (IsLoadedLand(position) || (position.IsEnv && Env(position) is not null));
}
