namespace AcPhys.Core;

/// <summary>
/// An immutable scene: loaded landblocks, env cells, buildings. Buildings are attached to land cells at construction
/// as a landblock load does (facts §5.3): origin AdjustToOutside'd against the block id; a building whose origin
/// falls in another block is discarded (listed in <see cref="Discarded"/>).
/// </summary>
public sealed class CellScene : IScene
{
    private readonly HashSet<LandblockId> loaded;
    private readonly bool allLoaded;
    private readonly Dictionary<CellId, EnvCell> cells = [];
    private readonly Dictionary<CellId, Building> buildings = [];

    /// <summary>Initializes a new instance.</summary>
    /// <param name="loadedBlocks">Loaded landblocks; every other block is unloaded.</param>
    /// <param name="envCells">Env cells (only those of loaded blocks are reachable).</param>
    /// <param name="buildingList">Buildings.</param>
    /// <exception cref="ArgumentException">Duplicate cell ids, or two buildings attached to one land cell.</exception>
    public CellScene(IEnumerable<LandblockId> loadedBlocks, IEnumerable<EnvCell> envCells, IEnumerable<Building> buildingList)
    {
        loaded = [.. loadedBlocks];
        foreach (var cell in envCells)
        {
            if (!cells.TryAdd(cell.Id, cell))
            {
                throw new ArgumentException($"duplicate env cell {cell.Id}", nameof(envCells));
            }
        }

        var discarded = new List<Building>();
        foreach (var b in buildingList)
        {
            var owner = b.OwningCell();
            if (owner.IsNone)
            {
                discarded.Add(b);
            }
            else if (!buildings.TryAdd(owner, b))
            {
                throw new ArgumentException($"two buildings attached to land cell {owner} (a SortCell holds one)", nameof(buildingList));
            }
        }

        Discarded = discarded;
    }

    /// <summary>Gets the open land scene: every block loaded, nothing indoors.</summary>
    public static CellScene Open { get; } = new([], [], []) { AllLoaded = true };

    private bool AllLoaded { init => allLoaded = value; }

    /// <summary>Gets the buildings discarded because their origin lies in another block.</summary>
    public IReadOnlyList<Building> Discarded { get; }

    /// <summary>Gets the attached buildings by owning land cell.</summary>
    public IReadOnlyDictionary<CellId, Building> Buildings => buildings;

    /// <inheritdoc/>
    public bool IsLoaded(LandblockId block) => allLoaded || loaded.Contains(block);

    /// <inheritdoc/>
    public EnvCell? GetEnvCell(CellId id) => cells.TryGetValue(id, out var c) && IsLoaded(id.Landblock) ? c : null;

    /// <inheritdoc/>
    public Building? GetBuilding(CellId landCell) => buildings.TryGetValue(landCell, out var b) && IsLoaded(landCell.Landblock) ? b : null;
}
