using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>The bundled reference core (AcPhys.Core) behind the adapter contract.</summary>
/// <param name="pick">The pick policy to declare and use.</param>
/// <param name="partsFidelity">Retail or ACE behaviour of the parts variant (facts §7 #3–#4).</param>
/// <param name="outdoor">Retail float32 outdoor math, or the exact double reference (<see cref="OutdoorPrecision.Double"/>).</param>
public sealed class ReferenceAdapter(PickPolicy pick = PickPolicy.Retail, PartsFidelity partsFidelity = default, OutdoorFidelity outdoor = default) : ICellPhysics
{
    [ThreadStatic]
    private static CellArray? scratch;

    // The array one walk's scene queries share under ace-keeps-stale-cells (see FindCellWalk); null: a fresh array per query.
    private CellArray? walkArray;

    /// <summary>Gets the shared retail instance (the adapter is stateless).</summary>
    public static ReferenceAdapter Instance { get; } = new();

    /// <summary>Gets the shared current-cell-first instance.</summary>
    public static ReferenceAdapter CurrentFirst { get; } = new(PickPolicy.CurrentFirst);

    /// <summary>Gets the retail-rules instance computed in the exact double-precision reference arithmetic (outdoor sets and pick).</summary>
    public static ReferenceAdapter Double { get; } = new(outdoor: OutdoorFidelity.Double);

    /// <inheritdoc/>
    public string Name => (pick == PickPolicy.Retail ? "reference" : "reference(current-first)")
        + (outdoor.Precision == OutdoorPrecision.Double ? "(double)" : string.Empty)
        + (partsFidelity.SameBlockGuard ? "+ace-same-block-guard" : string.Empty) + (partsFidelity.EveryPartAnchors ? "+ace-every-part-anchors" : string.Empty)
        + string.Concat(FidelityNames.Names(Indoor, default).Select(n => "+" + n)) + (Volumes == VolumeMode.Aabb ? "+aabb" : string.Empty);

    /// <inheritdoc/>
    public Op Ops => Op.All;

    /// <inheritdoc/>
    public OutdoorFidelity Outdoor => outdoor;

    /// <summary>Gets or initializes the indoor fidelity used by scene queries (retail by default).</summary>
    public IndoorFidelity Indoor { get; init; }

    /// <summary>Gets or initializes how scene cells are modelled: retail BSP semantics or the ACME AABB.</summary>
    public VolumeMode Volumes { get; init; }

    /// <inheritdoc/>
    public PickPolicy Pick => pick;

    /// <inheritdoc/>
    public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => LandDefs.BlockIdToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public bool GidToLcoord(CellId id, out Lcoord lcoord) => LandDefs.GidToLcoord(id, out lcoord);

    /// <inheritdoc/>
    public CellId LcoordToGid(int x, int y) => LandDefs.LcoordToGid(x, y);

    /// <inheritdoc/>
    public bool InboundValidCellId(CellId id) => LandDefs.InboundValidCellId(id);

    /// <inheritdoc/>
    public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => LandDefs.GetOutsideLcoord(id, x, y, out lcoord);

    /// <inheritdoc/>
    public AdjustResult AdjustToOutside(CellId id, float x, float y)
    {
        bool ok = LandDefs.AdjustToOutside(ref id, ref x, ref y);
        return new AdjustResult(ok, id, x, y);
    }

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => OutsideCells(cell, System.Numerics.Vector3.Zero, spheres);

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres)
    {
        var array = scratch ??= new CellArray();
        array.Reset();
        OutdoorCells.AddAllOutsideCells(array, cell, origin, [.. spheres], OpenLand.Instance, outdoor);
        return array.ToIdArray();
    }

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(cell, System.Numerics.Vector3.Zero, spheres, current);

    /// <inheritdoc/>
    public FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current)
    {
        if (!cell.IsLand)
        {
            // An env cell or block id position is indoor by its low word (facts §1.1, §4 step 3): it is seeded as itself,
            // and on open land no env cell is loaded, so there is no transit and no pick; id 0 has no visible cell.
            // Only the full find_cell_list says so; the outdoor-only CellQuery would treat them as their outdoor column.
            return FindCell(null, cell, spheres, current, false);
        }

        var array = scratch ??= new CellArray();
        var containing = CellQuery.FindCellListOutdoor(array, cell, origin, [.. spheres], current, pick, OpenLand.Instance, outdoor);
        return new FindCellResult(array.ToIdArray(), containing) { Loaded = LoadedFlags(array), HitsInteriorCell = false };
    }

    /// <inheritdoc/>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(scene, cell, spheres, current, false);

    /// <inheritdoc/>
    public FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells)
    {
        var array = walkArray ?? (scratch ??= new CellArray());
        if (walkArray is null)
        {
            array.Reset(); // a query outside a walk starts from an empty array, stale cells declared or not
        }

        var built = scene is null ? CellScene.Open : SceneBuild.Build(scene, Volumes);
        var result = SceneQuery.FindCellList(array, built, cell, [.. spheres], current, new CellQueryOptions(pick, true, loadCells, Indoor));
        return new FindCellResult(array.ToIdArray(), result.Containing) { HitsInteriorCell = result.HitsInteriorCell, Loaded = LoadedFlags(array) };
    }

    /// <summary>
    /// Answers a whole walk. Under ace-keeps-stale-cells the walk's queries share one array that is never cleared (facts
    /// §7 #6: ACE's Transition owns one fresh array, TR:604-611, so stale cells accumulate across its steps): the life of
    /// the stale array is one walk, and every walk starts from an empty one (docs/conformance.md, "Declared modes").
    /// </summary>
    /// <param name="walk">The walk.</param>
    /// <returns>One answer per query.</returns>
    public IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) =>
        WalkThread.AskEach(Indoor.AceKeepsStaleCells && walkArray is null ? WalkSession() : this, walk);

    /// <summary>
    /// Returns this reference with an array of its own that its scene queries share until it is dropped: what one walk
    /// asks an implementation declaring ace-keeps-stale-cells, asked query by query in the same order (the conformance
    /// invariants follow the queries the tool sent the implementation this way).
    /// </summary>
    /// <returns>A new adapter, in this one's mode, with an empty array.</returns>
    public ReferenceAdapter WalkSession() =>
        new(pick, partsFidelity, outdoor) { Indoor = Indoor, Volumes = Volumes, walkArray = new CellArray() };

    private static bool[] LoadedFlags(CellArray array)
    {
        var flags = new bool[array.Count];
        for (int i = 0; i < flags.Length; i++)
        {
            flags[i] = array[i].Loaded;
        }

        return flags;
    }

    /// <inheritdoc/>
    /// <remarks>Core's <see cref="ScenePartsQuery"/> in this adapter's indoor, parts and volume modes; a fresh array per query,
    /// stale cells declared or not (their array lives for one walk: <see cref="FindCellPartsWalk"/>).</remarks>
    public FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(parts);
        var array = scratch ??= new CellArray();
        array.Reset();
        bool hits = ScenePartsQuery.FindCellList(array, SceneBuild.Build(scene, Volumes), [.. parts], loadCells, Indoor with { AceKeepsStaleCells = false }, partsFidelity);
        return new FindCellResult(array.ToIdArray(), CellId.None) { HitsInteriorCell = hits, Loaded = LoadedFlags(array) };
    }

    /// <summary>
    /// Answers one walk's parts queries of one kind. Under ace-keeps-stale-cells they share one array that is never
    /// cleared (facts §4 step 1, §7 #6: ACE's find_bbox_cell_list resets only the AddedOutside latch, §3.5, and keeps the
    /// cells), so each answer holds the previous answer's cells unless the closure or the filter removes them; the array
    /// lives for this one call, one walk of one kind, and starts empty. Otherwise each query is a fresh one, as
    /// <see cref="FindCellParts"/> asks it.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="queries">The walk's parts queries, in order.</param>
    /// <param name="loadCells">True for the transition kind.</param>
    /// <returns>One answer per query.</returns>
    public IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells)
    {
        ArgumentNullException.ThrowIfNull(scene);
        ArgumentNullException.ThrowIfNull(queries);
        var answers = new FindCellResult[queries.Count];
        if (!Indoor.AceKeepsStaleCells)
        {
            for (int i = 0; i < answers.Length; i++)
            {
                answers[i] = FindCellParts(scene, queries[i], loadCells);
            }

            return answers;
        }

        var array = new CellArray();
        var built = SceneBuild.Build(scene, Volumes);
        for (int i = 0; i < answers.Length; i++)
        {
            bool hits = ScenePartsQuery.FindCellList(array, built, [.. queries[i]], loadCells, Indoor, partsFidelity);
            answers[i] = new FindCellResult(array.ToIdArray(), CellId.None) { HitsInteriorCell = hits, Loaded = LoadedFlags(array) };
        }

        return answers;
    }

    /// <inheritdoc/>
    public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts)
    {
        var array = scratch ??= new CellArray();
        array.Reset();
        if (parts.Count > 0)
        {
            OutdoorParts.AddAllOutsideCells(array, [.. parts], parts[0].Cell, OpenLand.Instance, partsFidelity);
        }

        return array.ToIdArray();
    }
}
