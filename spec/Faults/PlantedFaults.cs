using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>The catalogue of planted faults and a factory for adapters that carry them.</summary>
public static class PlantedFaults
{
    /// <summary>Truncation toward zero instead of floor in get_outside_lcoord.</summary>
    public static readonly PlantedFault TruncFloor = new(
        "trunc-floor",
        "get_outside_lcoord truncates x/24 toward zero instead of flooring",
        "facts §6.2: negative block-local coordinates are normal near west/south edges; (int)(x/24) maps x = −0.5 into cell 0 of the same block instead of the previous block.",
        ["OUTSIDE-LCOORD-GEOMETRY", "ADJUST-GEOMETRY", "ADJUST-RANGE"]);

    /// <summary>NaN converted to an int before the range check.</summary>
    public static readonly PlantedFault NanAsZero = new(
        "nan-as-zero",
        "get_outside_lcoord converts to int before the range test, so NaN becomes lcoord 0",
        "issue #2: since .NET 9 (int)float.NaN is 0 on x64 (saturating conversions), so a port that range-tests the int accepts NaN as column 0.",
        ["NONFINITE-REJECTED", "NONFINITE-SPHERE-ENDS-LOOP"]);

    /// <summary>Map edge off by one.</summary>
    public static readonly PlantedFault MapEdge2040 = new(
        "map-edge-2040",
        "in_bounds tests ≤ 2040 instead of < 2040",
        "facts §6.3: lcoord 2040 is off the map (block byte 0xFF); an off-by-one range test manufactures ids in block 0xFF.",
        ["MAP-EDGE", "OUTSIDE-LCOORD-GEOMETRY"]);

    /// <summary>Sign-extended block_y byte.</summary>
    public static readonly PlantedFault SignExtendBlockY = new(
        "sign-extend-by",
        "block_y read as a signed byte",
        "seed (#106 commit): a decompiler rendered block_y as int8_t; blocks 0x80..0xFE then get negative lcoords.",
        ["LCOORD-ROUNDTRIP", "LCOORD-BLOCK", "OUTSIDE-LCOORD-GEOMETRY"]);

    /// <summary>Dropped 192 m block-length constant in the re-base.</summary>
    public static readonly PlantedFault DropBlockLength = new(
        "drop-block-length",
        "AdjustToOutside re-bases with v − ⌊v/192⌋ (the 192 m factor dropped)",
        "seed (#106 commit): a decompiler dropped the 192f BlockLength constant from the re-base.",
        ["ADJUST-RANGE", "ADJUST-PRESERVES-POSITION"]);

    /// <summary>Missing EPS snap.</summary>
    public static readonly PlantedFault NoEpsSnap = new(
        "no-eps-snap",
        "AdjustToOutside does not snap |v| < EPS to 0",
        "facts §2.1 step 2, §6.4: without the snap −0.0001 moves to the previous block and a tiny negative re-bases to exactly 192.",
        ["ADJUST-GEOMETRY", "ADJUST-RANGE"]);

    /// <summary>ACE's X-only inbound_valid_cellid.</summary>
    public static readonly PlantedFault InboundXOnly = new(
        "inbound-x-only",
        "inbound_valid_cellid checks block X only (ACE)",
        "facts §7 #15: ACE tests only bx; retail tests bx and by, so 0x00FF0001 is valid in ACE.",
        ["MAP-EDGE"]);

    /// <summary>The #106 clamp.</summary>
    public static readonly PlantedFault Clamp106 = new(
        "clamp-106",
        "candidates and the containing pick clamped to the current landblock",
        "seed (acdream #106): the port clamped add_all_outside_cells and the pick to the current block's 8 × 8 grid; one step over a block line left no candidate containing the centre and the cell froze (10,449 frames in one capture).",
        ["NO-BOUNDARY-FREEZE", "COVERAGE", "NEIGHBOUR-SYMMETRY"]);

    /// <summary>Neighbours from in-cell coordinates.</summary>
    public static readonly PlantedFault InCellNeighbours = new(
        "in-cell-neighbours",
        "check_add_cell_boundary works on the in-block cell index, so no neighbour across a block line is added",
        "issue #3: an early ACE revision computed neighbours from in-cell (block-local) coordinates instead of global lcoords.",
        ["COVERAGE"]);

    /// <summary>Else-branch diagonal.</summary>
    public static readonly PlantedFault ElseDiagonal = new(
        "else-diagonal",
        "the west-side test is an else branch of the east-side test",
        "issue #5: early ACE's else-branch; with r > 12 both sides must be added (facts §3.2).",
        ["COVERAGE"]);

    /// <summary>Inverted sphere-count guard.</summary>
    public static readonly PlantedFault SphereGuardInverted = new(
        "sphere-guard-inverted",
        "add_all_outside_cells takes the no-sphere path when there are spheres",
        "issue #5: an inverted numSphere guard adds only the position's own cell.",
        ["COVERAGE"]);

    /// <summary>One sphere's re-seated cell leaks into the next.</summary>
    public static readonly PlantedFault SphereLeak = new(
        "sphere-leak",
        "the next sphere starts from the previous sphere's re-seated cell instead of the position's",
        "issue #5: a port reused the cell variable across the sphere loop (facts §3.3 a: each sphere starts from position.ObjCellID).",
        ["COVERAGE", "SOUNDNESS"]);

    /// <summary>Array not reset between calls.</summary>
    public static readonly PlantedFault NoReset = new(
        "no-reset",
        "the cell array keeps the previous query's cells",
        "facts §7 #6: ACE's find_cell_list does not clear its dictionary; retail truncates the array.",
        ["SOUNDNESS"]);

    /// <summary>Declares hysteresis, does not implement it.</summary>
    public static readonly PlantedFault NoHysteresis = new(
        "no-hysteresis",
        "declares the current-cell-first pick but implements the retail rule",
        "issue #4: acdream's hysteresis lost in a refactor; the cell flickers on a shared edge.",
        ["HYSTERESIS"]);

    /// <summary>Declares the retail pick, keeps the current cell.</summary>
    public static readonly PlantedFault StickyPick = new(
        "sticky-pick",
        "declares the retail pick but keeps the current cell while it contains the centre",
        "issue #3: a retail-declared port with a hidden hysteresis; on a shared edge the cell then depends on the path, not the position.",
        ["STABLE-PICK", "WALK-REVERSIBLE"]);

    /// <summary>ACE's add_cell_block guard applied to movers.</summary>
    public static readonly PlantedFault AceSameBlockGuard = new(
        "ace-same-block-guard",
        "add_cell_block skips cells outside the calling cell's landblock (ACE's FIXME guard)",
        "facts §7 #3 and the seed: ACE's guard, an ACE divergence; applied to a mover it drops every cell across a block line.",
        ["PARTS-COVERAGE"]);

    /// <summary>ACE's every-part-anchor parts variant.</summary>
    public static readonly PlantedFault AceEveryPartAnchors = new(
        "ace-every-part-anchors",
        "every part anchors its own add_cell_block over a range that only grows (ACE)",
        "facts §7 #4: ACE makes every part an anchor and never resets the running range, so a multi-part object spills into cells none of its boxes touch; retail uses the first part only.",
        ["PARTS-SOUNDNESS"]);

    /// <summary>No cell for a query without spheres.</summary>
    public static readonly PlantedFault NoSphereNoCell = new(
        "no-sphere-no-cell",
        "outside_cells / find_cell with an empty sphere list add nothing",
        "issue #18 (a real port): facts §3.3 step 3 re-seats the position itself and adds its one cell when numSphere is 0; the port's loop over spheres simply ran zero times.",
        ["OUTSIDE-CELLS-CONFORMANCE", "FIND-CELL-QUERY-CONFORMANCE"]);

    /// <summary>The no-sphere path re-seats (0, 0) instead of the position's own point.</summary>
    public static readonly PlantedFault NoSphereOriginIgnored = new(
        "no-sphere-origin-ignored",
        "with no spheres the position's cell is taken at its block's (0, 0), not at the position's own point",
        "facts §3.3 step 3: AdjustToOutside runs on the caller's Position; a port that only had the cell id added the block's first cell.",
        ["OUTSIDE-CELLS-CONFORMANCE", "FIND-CELL-QUERY-CONFORMANCE"]);

    /// <summary>An env, block-id or id-0 position is its own containing cell on open land.</summary>
    public static readonly PlantedFault EnvPositionContains = new(
        "env-position-contains",
        "find_cell from an env-cell, block-id or id-0 position on open land answers no candidates and the position as the containing cell",
        "issue #18 (a real port): retail seeds an indoor position as itself (facts §4 step 3) and, with no env cell loaded, has no transit and no pick; id 0 has no visible cell at all.",
        ["FIND-CELL-QUERY-CONFORMANCE"]);

    /// <summary>blockid_to_lcoord(0) succeeds.</summary>
    public static readonly PlantedFault BlockIdZeroOk = new(
        "blockid-zero-ok",
        "blockid_to_lcoord(0) answers (0, 0) ok (ACE)",
        "facts §2 blockid_to_lcoord, §7 #16: ACE returns (0,0) for id 0; retail reports failure (SceneTool.c @122259).",
        ["LANDDEFS-CONFORMANCE"]);

    /// <summary>Touching counts as overlapping in check_add_cell_boundary.</summary>
    public static readonly PlantedFault TouchInclusive = new(
        "touch-inclusive",
        "check_add_cell_boundary uses >= / <= where retail is strict",
        "facts §3.2, §6.7: every comparison is strict, so a disc that exactly touches a cell line (pt.x == r) adds no neighbour; an inclusive test adds one.",
        ["OUTSIDE-CELLS-CONFORMANCE", "FIND-CELL-QUERY-CONFORMANCE"]);

    /// <summary>The first outdoor cell containing the centre wins.</summary>
    public static readonly PlantedFault FirstHitOutdoorPick = new(
        "first-hit-outdoor-pick",
        "the outdoor pick keeps the first candidate whose square contains the centre (retail: the last)",
        "facts §4 step 4b, §6.5: outdoor hits do not stop the scan, so on an exact line the last candidate containing the centre wins; a port that breaks on the first hit picks the other cell.",
        ["FIND-CELL-QUERY-CONFORMANCE"]);

    /// <summary>Checked conversion: a non-finite or huge coordinate throws.</summary>
    public static readonly PlantedFault CheckedCast = new(
        "checked-cast",
        "get_outside_lcoord converts ⌊x/24⌋ with a checked cast, so NaN, ±∞ and huge coordinates throw OverflowException",
        "facts §6.15, §6.17: a port that guards the .NET 9 saturating cast with `checked` trades silent garbage for an exception on every non-finite or |x| > 5·10¹⁰ centre; every operation must answer every input.",
        ["NONFINITE-REJECTED", "NONFINITE-SPHERE-ENDS-LOOP"]);

    /// <summary>Gets every planted fault.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } =
    [
        TruncFloor, NanAsZero, MapEdge2040, SignExtendBlockY, DropBlockLength, NoEpsSnap, InboundXOnly,
        Clamp106, InCellNeighbours, ElseDiagonal, SphereGuardInverted, SphereLeak, NoReset, NoHysteresis, StickyPick, AceSameBlockGuard, AceEveryPartAnchors,
        NoSphereNoCell, NoSphereOriginIgnored, EnvPositionContains, BlockIdZeroOk, TouchInclusive, FirstHitOutdoorPick, CheckedCast,
        .. IndoorFaults.All, .. PartsIndoorFaults.All, .. PartsFrameFaults.All, .. PartsShapeFaults.All, .. PartsStaleFaults.All,
        .. PortShimFaults.All,
        .. PartsObjectFaults.All,
    ];

    /// <summary>No defect: the fault model as it is when nothing is switched on (tests compare it with core).</summary>
    internal static readonly PlantedFault NoFault = new("none", "no defect", "the model itself", []);

    /// <summary>Returns the fault model with nothing switched on; it must answer exactly as the reference core.</summary>
    /// <returns>The model.</returns>
    internal static ICellPhysics Model() => new FaultyPhysics(NoFault);

    /// <summary>Finds a fault by id.</summary>
    /// <param name="id">The fault id.</param>
    /// <returns>The fault, or null.</returns>
    public static PlantedFault? Find(string id) => All.FirstOrDefault(f => string.Equals(f.Id, id, StringComparison.OrdinalIgnoreCase));

    /// <summary>
    /// Returns the outdoor fault model with several faults switched on at once: a port with more than one bug, to show
    /// that a run reports the second behind the first (issue #18).
    /// </summary>
    /// <param name="ids">Fault ids of the outdoor / LandDefs model (not the indoor, parts or scene faults).</param>
    /// <returns>The faulty adapter.</returns>
    /// <exception cref="ArgumentException">An id is unknown or not one of the model's faults.</exception>
    public static ICellPhysics Combine(params string[] ids)
    {
        var faults = ids.Select(id => Find(id) is { } f && IndoorFaults.Create(f) is null && PartsIndoorFaults.Create(f) is null && PartsFrameFaults.Create(f) is null && PartsObjectFaults.Create(f) is null && PartsStaleFaults.Create(f) is null && !PortShimFaults.All.Contains(f) && !f.Id.StartsWith("ace-", StringComparison.Ordinal)
            ? f
            : throw new ArgumentException($"'{id}' is not a fault of the outdoor model", nameof(ids))).ToArray();
        return new FaultyPhysics(faults);
    }

    /// <summary>Returns the reference implementation with the named fault switched on.</summary>
    /// <param name="id">The fault id.</param>
    /// <returns>The faulty adapter.</returns>
    /// <exception cref="ArgumentException">No fault has that id.</exception>
    public static ICellPhysics Create(string id)
    {
        var fault = Find(id) ?? throw new ArgumentException(
            $"unknown fault '{id}'; known: {string.Join(", ", All.Select(f => f.Id))}", nameof(id));
        return fault.Id switch
        {
            "ace-same-block-guard" => new ReferenceAdapter(PickPolicy.Retail, new PartsFidelity(SameBlockGuard: true)),
            "ace-every-part-anchors" => new ReferenceAdapter(PickPolicy.Retail, new PartsFidelity(EveryPartAnchors: true)),
            _ => PortShimFaults.Create(fault) ?? IndoorFaults.Create(fault) ?? PartsIndoorFaults.Create(fault) ?? PartsFrameFaults.Create(fault) ?? PartsObjectFaults.Create(fault) ?? PartsStaleFaults.Create(fault) ?? new FaultyPhysics(fault),
        };
    }
}
