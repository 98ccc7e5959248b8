using AcPhys.Core;

namespace AcPhys.Contract;

/// <summary>
/// The adapter contract: what an implementation under test offers. A partial implementation announces what it
/// has in <see cref="Ops"/>; invariants that need anything else are reported as not tested, never as passed.
/// </summary>
/// <remarks>
/// Methods for operations outside <see cref="Ops"/> may throw <see cref="NotSupportedException"/>. Any other
/// exception is a finding: the LandDefs operations are total and must answer every input.
/// An adapter that cannot reach its implementation (a crashed or hung process) throws <see cref="AdapterFailureException"/>.
/// <para>Three ways in: the bundled <see cref="ReferenceAdapter"/>; a .NET class implementing this interface, loaded with
/// <c>acphys verify --impl Adapter.dll</c>; or any program speaking protocol v1 on stdin/stdout
/// (<c>AcPhys.Protocol.Client.ProcessAdapter</c> in the AcPhys.Protocol assembly, <c>acphys verify --impl-cmd</c>, docs/protocol.md), whose op names are
/// <see cref="OpNames"/>.</para>
/// </remarks>
public interface ICellPhysics
{
    /// <summary>Gets the implementation's name, for reports.</summary>
    string Name { get; }

    /// <summary>Gets the operations this implementation offers.</summary>
    Op Ops { get; }

    /// <summary>Gets the containing-cell pick policy the implementation declares (retail when it says nothing).</summary>
    PickPolicy Pick { get; }

    /// <summary><c>blockid_to_lcoord</c>: (8·bx, 8·by) of the id's landblock.</summary>
    /// <param name="id">Any id.</param>
    /// <param name="lcoord">The result on success.</param>
    /// <returns>Success.</returns>
    bool BlockIdToLcoord(CellId id, out Lcoord lcoord);

    /// <summary><c>gid_to_lcoord</c>: the global lcoord of a land cell id.</summary>
    /// <param name="id">Any id.</param>
    /// <param name="lcoord">The result on success.</param>
    /// <returns>Success.</returns>
    bool GidToLcoord(CellId id, out Lcoord lcoord);

    /// <summary><c>lcoord_to_gid</c>: the land cell id of an lcoord, or id 0 off the map.</summary>
    /// <param name="x">Global column.</param>
    /// <param name="y">Global row.</param>
    /// <returns>The id.</returns>
    CellId LcoordToGid(int x, int y);

    /// <summary><c>inbound_valid_cellid</c>.</summary>
    /// <param name="id">Any id.</param>
    /// <returns>Validity.</returns>
    bool InboundValidCellId(CellId id);

    /// <summary><c>get_outside_lcoord</c>: the lcoord of the 24 m column containing a block-frame point.</summary>
    /// <param name="id">Any id.</param>
    /// <param name="x">Block-frame x.</param>
    /// <param name="y">Block-frame y.</param>
    /// <param name="lcoord">The result on success.</param>
    /// <returns>Success.</returns>
    bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord);

    /// <summary><c>adjust_to_outside</c>: re-seat (id, x, y) to the land cell under the point.</summary>
    /// <param name="id">Any id.</param>
    /// <param name="x">Block-frame x.</param>
    /// <param name="y">Block-frame y.</param>
    /// <returns>The outcome.</returns>
    AdjustResult AdjustToOutside(CellId id, float x, float y);

    /// <summary><c>outside_cells</c>: the land cells the spheres touch, in insertion order, every landblock loaded.</summary>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame.</param>
    /// <returns>The cell ids in insertion order.</returns>
    IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres);

    /// <summary><c>find_cell</c> on open land: the candidate cells and the containing cell.</summary>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame; sphere 0 decides the pick.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <returns>The cells and the containing cell (<see cref="CellId.None"/> when none).</returns>
    FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current);

    /// <summary><c>outside_cells_parts</c>: the land cells the parts' boxes cover (first part the anchor and the caller), every block loaded.</summary>
    /// <param name="parts">The parts.</param>
    /// <returns>The cell ids in insertion order.</returns>
    IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts);

    /// <summary>
    /// <c>find_cell_scene</c>: find_cell_list over a scene (facts §4, §5), or on open land when <paramref name="scene"/> is null.
    /// The pick runs; the indoor visibility filter is on (LoadCells false), so candidates of an indoor position are
    /// its cell and the cells it sees. Offered when <see cref="Ops"/> has <see cref="Op.FindCellScene"/>.
    /// </summary>
    /// <param name="scene">The scene, or null for open land.</param>
    /// <param name="cell">The position's cell id (land or env).</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame; sphere 0 decides the pick.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <returns>The cells (load hints included) and the containing cell.</returns>
    FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current) =>
        scene is null ? FindCell(cell, spheres, current) : throw new NotSupportedException("find_cell_scene");

    /// <summary>
    /// <c>find_cell_scene</c> as a movement transition asks it (LoadCells true: retail's CTransition sets
    /// do_not_load_cells = 0, so the indoor visibility filter does not run, facts §4 step 5, §6.14). Offered when
    /// <see cref="Ops"/> has <see cref="Op.FindCellTransition"/>; with <paramref name="loadCells"/> false it is
    /// <see cref="FindCell(Scene?, CellId, IReadOnlyList{Sphere}, CellId)"/>.
    /// </summary>
    /// <param name="scene">The scene, or null for open land.</param>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <param name="loadCells">True for a transition query (no visibility filter).</param>
    /// <returns>The cells and the containing cell.</returns>
    FindCellResult FindCell(Scene? scene, CellId cell, IReadOnlyList<Sphere> spheres, CellId current, bool loadCells) =>
        loadCells ? throw new NotSupportedException("find_cell_transition") : FindCell(scene, cell, spheres, current);

    /// <summary>
    /// <c>find_cell_parts_scene</c> / <c>find_cell_parts_transition</c>: the parts / bounding-box cell list over a scene
    /// (retail's find_bbox_cell_list; facts §3.4, §5.2, §5.3; docs/indoor.md, "Parts indoors"). The first part is the
    /// anchor: its cell seeds the list (an env cell as itself, a land cell through the parts add_all_outside_cells),
    /// the closure runs each cell's parts transit (an env cell's portals, a land cell's building portals), and static
    /// placement (<paramref name="loadCells"/> false) runs the indoor visibility filter. There is no containing-cell
    /// pick: <see cref="FindCellResult.Containing"/> is <see cref="CellId.None"/>. Offered when <see cref="Ops"/> has
    /// <see cref="Op.FindCellPartsScene"/> (static) or <see cref="Op.FindCellPartsTransition"/> (transition); the default
    /// offers neither, so an implementation that does not override it is reported NOT TESTED on the parts indoors.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="parts">The parts (each in its own cell's block frame); the first is the anchor.</param>
    /// <param name="loadCells">True for a transition query (no visibility filter).</param>
    /// <returns>The cells in insertion order (load hints included, <see cref="FindCellResult.Loaded"/>), no containing cell.</returns>
    FindCellResult FindCellParts(Scene scene, IReadOnlyList<Part> parts, bool loadCells) =>
        throw new NotSupportedException(loadCells ? "find_cell_parts_transition" : "find_cell_parts_scene");

    /// <summary>
    /// <c>find_cell_parts_walk</c>: one walk's parts queries of one kind, in order, one answer each. The default asks each
    /// query through <see cref="FindCellParts"/>, so an implementation that does not override it answers exactly as when
    /// asked query by query; one declaring ace-keeps-stale-cells overrides it, since its array lives for the walk (facts
    /// §4 step 1, §7 #6: ACE does not clear the cells, so each answer keeps the previous answer's), and an adapter across
    /// a process boundary overrides it to answer the walk in one round trip.
    /// </summary>
    /// <param name="scene">The scene.</param>
    /// <param name="queries">The walk's parts queries, in order (each anchored by its first part).</param>
    /// <param name="loadCells">True for the transition kind, false for static placement.</param>
    /// <returns>One answer per query.</returns>
    IReadOnlyList<FindCellResult> FindCellPartsWalk(Scene scene, IReadOnlyList<IReadOnlyList<Part>> queries, bool loadCells)
    {
        ArgumentNullException.ThrowIfNull(queries);
        var answers = new FindCellResult[queries.Count];
        for (int i = 0; i < answers.Length; i++)
        {
            answers[i] = FindCellParts(scene, queries[i], loadCells);
        }

        return answers;
    }

    /// <summary>
    /// <c>outside_cells</c> with the position's own point (block frame), which retail uses only when
    /// <paramref name="spheres"/> is empty (facts §3.3 step 3). The default ignores the point: override it.
    /// </summary>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="origin">The position's point in <paramref name="cell"/>'s block frame.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame.</param>
    /// <returns>The cells, in insertion order.</returns>
    IReadOnlyList<CellId> OutsideCells(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres) => OutsideCells(cell, spheres);

    /// <summary><c>find_cell</c> on open land with the position's own point (used only with no spheres, facts §3.3 step 3). The default ignores the point: override it.</summary>
    /// <param name="cell">The position's cell id.</param>
    /// <param name="origin">The position's point in <paramref name="cell"/>'s block frame.</param>
    /// <param name="spheres">Centres in <paramref name="cell"/>'s block frame.</param>
    /// <param name="current">The current cell, or <see cref="CellId.None"/>.</param>
    /// <returns>The candidates and the containing cell.</returns>
    FindCellResult FindCell(CellId cell, System.Numerics.Vector3 origin, IReadOnlyList<Sphere> spheres, CellId current) => FindCell(cell, spheres, current);

    /// <summary>
    /// <c>find_cell_walk</c>: a whole walk, one answer per query (the start, then each step), threaded by
    /// <see cref="WalkThread"/> — the rule the tool's walk runners use. The default asks each query through the
    /// single-query operations above, so an adapter that does not override it behaves exactly as when asked step by step;
    /// an adapter across a process boundary overrides it to answer the walk in one round trip.
    /// </summary>
    /// <param name="walk">The walk.</param>
    /// <returns>One answer per query, <see cref="WalkRequest.Queries"/> of them.</returns>
    IReadOnlyList<FindCellResult> FindCellWalk(WalkRequest walk) => WalkThread.AskEach(this, walk);

    /// <summary>
    /// Gets the documented indoor deviations the implementation declares (facts §7 #6–#13; retail when it says
    /// nothing). The conformance invariants compare it with the reference in the same mode, never failing it for them.
    /// </summary>
    IndoorFidelity Indoor => IndoorFidelity.Retail;

    /// <summary>Gets the documented outdoor deviations the implementation declares (facts §7 #2; the double-precision mode).</summary>
    OutdoorFidelity Outdoor => OutdoorFidelity.Retail;
}

/// <summary>The answer of <c>find_cell</c>.</summary>
/// <param name="Cells">Candidate cells in insertion order.</param>
/// <param name="Containing">The containing cell, or <see cref="CellId.None"/>.</param>
public sealed record FindCellResult(IReadOnlyList<CellId> Cells, CellId Containing)
{
    /// <summary>Gets HitsInteriorCell as the implementation reported it, or null when it did not (protocol v1 makes it optional).</summary>
    public bool? HitsInteriorCell { get; init; }

    /// <summary>
    /// Gets, parallel to <see cref="Cells"/>, whether each entry is a loaded cell (false: a load hint, retail's null
    /// payload, facts §3.1, §5.1), or null when the implementation did not report it.
    /// </summary>
    public IReadOnlyList<bool>? Loaded { get; init; }
}
