namespace AcPhys.Props.Coverage;

/// <summary>
/// The facts-coverage matrix (issue 27): every section, step and pitfall of the facts and every ACE difference of §7,
/// with the class that reaches it and what breaks it. docs/facts-coverage.md is this list with its pr-profile counts.
/// </summary>
internal static class FactsMatrix
{
    private const string LandDefs = "LANDDEFS-CONFORMANCE";
    private const string Outside = "OUTSIDE-CELLS-CONFORMANCE";
    private const string Query = "FIND-CELL-QUERY-CONFORMANCE";
    private const string Walks = "FIND-CELL-CONFORMANCE";

    /// <summary>Gets the rows, in facts order.</summary>
    public static IReadOnlyList<FactsRule> Rows { get; } =
    [
        new("§1.1", "cell id layout: low-word ranges, 0xFF block byte invalid", "cell:invalid-low", null, LandDefs),
        new("§1.1", "block bytes are unsigned", "cell:high-byte", "fault:sign-extend-by", "LCOORD-BLOCK"),
        new("§1.2, §1.3", "land index X-major; lcoord < 2040 (pitfall 3)", "lcoord:off-map", "fault:map-edge-2040", LandDefs),
        new("§1.4, §1.5", "closed 24 m squares; EPS and 0.01 tolerances", "centre:on-cell-line", null, Query),
        new("§2 get_outside_lcoord", "floor toward −∞, not truncation (pitfall 2)", "coord:negative", "fault:trunc-floor", "OUTSIDE-LCOORD-GEOMETRY"),
        new("§2 inbound_valid_cellid, §7 #15", "retail tests block X and Y", "cell:byte-FF", "fault:inbound-x-only", "MAP-EDGE"),
        new("§2 blockid_to_lcoord, §7 #16", "retail fails id 0", "cell:zero", "fault:blockid-zero-ok", LandDefs),
        new("§2.1 step 2, pitfall 4", "AdjustToOutside EPS snap", "coord:eps-band", "fault:no-eps-snap", "ADJUST-GEOMETRY"),
        new("§2.1 step 4", "re-base by 192·⌊v/192⌋", "coord:line-192", "fault:drop-block-length", "ADJUST-RANGE"),
        new("§6 pitfall 17", "non-finite coordinates rejected (hardening)", "coord:nonfinite", "fault:nan-as-zero", "NONFINITE-REJECTED"),
        new("§6 pitfall 15", "no runtime-dependent casts", "coord:huge", "fault:checked-cast", "NONFINITE-REJECTED"),
        new("§3.1, pitfall 1", "global lcoord grid, no clamp to the block", "centre:near-block-line", "fault:clamp-106", Outside),
        new("§3.2, pitfall 7", "strict comparisons: a touching disc adds nothing", "radius:touches-edge", "fault:touch-inclusive", Outside),
        new("§3.2 steps 1–2", "both x branches fire when r > 12", "radius:>12", "fault:else-diagonal", Outside),
        new("§3.3 step 2", "cross-block neighbours from the global grid", "centre:near-block-line", "fault:in-cell-neighbours", Outside),
        new("§3.3 step 2a", "each sphere starts from the position", "spheres:multi", "fault:sphere-leak", Outside),
        new("§3.3 step 3", "no spheres: the position's own cell", "query:no-spheres", "fault:no-sphere-no-cell", Outside),
        new("§3.3 steps 2–3", "the sphere path is taken when there are spheres", "query:no-spheres", "fault:sphere-guard-inverted", Outside),
        new("§3.4, §7 #3", "add_cell_block: no same-block guard", "parts:multi", "fault:ace-same-block-guard", "PARTS-COVERAGE"),
        new("§3.4, §7 #4", "parts: the first part anchors one call", "parts:multi", "fault:ace-every-part-anchors", "PARTS-SOUNDNESS"),
        new("§3.5, §7 #1", "AddedOutside latch", null, null, null, "membership is the same with or without the latch (facts §3.3 step 1: re-running with the same inputs is idempotent)"),
        new("§4 step 1, §7 #6, pitfall 13", "the array is reset each call (open land)", "centre:interior", "fault:no-reset", Query),
        new("§4 step 1, §7 #6", "the array is reset each call (scenes)", "route:EnterAndBack", "deviation:ace-keeps-stale-cells", Walks),
        new("§4 steps 2–3, pitfall 12", "env / block-id positions map to the outdoor column", "position:env", "fault:env-position-contains", Query),
        new("§4 step 4a, pitfall 6", "closure re-reads the count (breadth-first)", "route:EnterAndBack", "fault:snapshot-closure", Walks),
        new("§4 step 4", "the pick runs after the closure", "route:Enter", "fault:pick-before-transit", Walks),
        new("§4 step 4b, pitfall 5", "last land hit wins", "centre:on-cell-line", "fault:first-hit-outdoor-pick", Query),
        new("§4 step 4b", "retail pick: no hysteresis", "centre:on-cell-line", "deviation:current-first", Query),
        new("§4 step 4b", "an env hit wins over land", "route:Enter", "fault:outdoor-wins", Walks),
        new("§4 step 4b, pitfall 6", "first env hit wins", "cell:overlap-stairwell", "fault:pick-last-env", Walks),
        new("§4 step 4b, pitfall 8", "only sphere 0 decides the pick", "body:mixed-radii", "fault:pick-last-sphere", "PORTAL-TRANSIT"),
        new("§4 step 4b, pitfall 11", "the pick subtracts GetBlockOffset", "place:across-block-line", "fault:no-reframe", Walks),
        new("§4 step 4b", "no containing cell: currCell null", "route:DungeonRun", "fault:keep-current-on-miss", Walks),
        new("§4 step 5", "static queries filter by VisibleCells", "route:Enter", "fault:no-visibility-filter", Walks),
        new("§4 step 5", "the filter never removes load hints", "dungeon:unloaded-tail", "fault:filter-drops-hints", Walks),
        new("§4 step 5, §7 #7", "the filter also runs after an interior pick", "route:Through", "deviation:ace-early-return", Walks),
        new("§4 step 5, §7 #8", "the filter inside the step-4 guard", null, null, null, "alone unobservable: outside the guard (no spheres, or the position's cell not loaded) a reset array holds only the position, which both keep (docs/indoor.md, find_cell_list step 4)"),
        new("§4 step 5, §7 #9, pitfall 14", "transitions do not filter", "route:Through", null, Walks),
        new("§4 outputs", "building entry sets HitsInteriorCell", "route:Enter", "fault:hits-interior-unset", Walks),
        new("§5.1 exit, pitfall 9", "exit only while a sphere straddles (−R < d < R)", "route:PortalJitter", "fault:exit-straddle-one-sided", Walks),
        new("§5.1 exit", "exit portals add the outdoor cells", "route:DungeonRun", "fault:no-exit-transit", Walks),
        new("§5.1 neighbour, §5.8", "neighbour tested in its own frame", "frame:per-cell", "fault:neighbour-wrong-frame", Walks),
        new("§5.1 neighbour", "neighbour's volume, not the portal plane", "graph:loop", "fault:neighbour-by-plane", Walks),
        new("§5.1 hint, §5.4", "load hint by PortalSide side test", "dungeon:unloaded-tail", "fault:hint-straddle-only", Walks),
        new("§5.4", "PortalSide = (Flags & 2) == 0", "dungeon:unloaded-tail", "fault:inverted-portal-side", Walks),
        new("§5.1 hint, §7 #11", "load hint keyed by the full id", "dungeon:unloaded-tail", "deviation:ace-load-hint-low-key", Walks),
        new("§5.1 neighbour, §7 #10", "neighbour among all loaded cells", "see:blind-neighbour", "deviation:ace-neighbour-via-visible-cells", Walks),
        new("§5.1, §5.4, §7 #12", "exit by flag 4, not OtherCellId 0xFFFF", null, "deviation:ace-outside-by-cell-id", null, "inexpressible, and not known to occur: scene files and dat exports derive flag 4 from \"outside\" (CellPortal.FlagsFor); the facts (§5.4) name both fields but no portal where they disagree, so no raw-flags field was added (docs/facts-coverage.md)"),
        new("§5.3", "every building portal, in order", "doors:2", "fault:building-first-portal-only", Walks),
        new("§5.3", "the break is in the sphere loop, not the portal loop", "walk:facade-sealed-seam", "fault:building-stop-first-room", Walks),
        new("§5.3", "portal id 0xFFFF skips the entry test", "door:invalid-marker", "fault:invalid-bld-portal-entered", Walks),
        new("§5.3, pitfall 8", "all spheres decide membership", "body:3-spheres", "fault:transit-sphere0-only", Walks),
        new("§5.3, §6.11", "no block offset in transit (retail)", "place:building-across-line", "deviation:reframe-transit", Walks),
        new("§5.2, §5.3 parts, §7 #14", "parts variants indoors", null, null, null, "not wired: the parts transit exists in core (EnvTransitParts) but no query, adapter op or invariant reaches it (docs/indoor.md, Not done)"),
        new("§5.5, §7 #13", "point_in_cell refuses a cell without portals", "cell:portal-less", "deviation:ace-no-portal-guard", Walks),
        new("§5.5, §5.3", "a portal-less cell is still a candidate", "cell:portal-less", "fault:portal-guard-in-transit", Walks),
        new("§5.6", "terrain triangulation", null, null, null, "no membership effect: the two triangles' union is the closed square whichever diagonal (facts §5.5)"),
        new("§5.7 point_inside", "Close (|d| ≤ EPS) is inside", "route:PortalJitter", "fault:close-is-outside", Walks),
        new("§5.7 sphere, pitfall 10", "+0.01 in the BSP sphere test", "route:Enter", "fault:sphere-test-unpadded", Walks),
        new("§5.7, pitfall 16", "positive chain only", "walk:door-room-second-piece", "fault:walks-negative-children", Walks),
        new("§5.9", "swap-removal order after the filter", "filter:mid-removal", "fault:filter-stable-order", Walks),
        new("§5.9, §4 step 5", "the entry swapped into a hole is tested too", "filter:mid-removal", "fault:filter-skips-swapped-in", Walks),
        new("§5.9, pitfall 6", "the filter walks front to back", "filter:mid-removal", "fault:filter-from-end", Walks),
        new("§5.9, pitfall 6", "the filter walks a snapshot, not the live array", "filter:recheck-order", "fault:filter-live-recheck", Walks),
        new("§6 pitfall 5", "stable retail pick on a line", "centre:on-cell-line", "fault:sticky-pick", "STABLE-PICK"),
        new("§7 #2", "unloaded land cells added as load hints", "place:unloaded-neighbours", "deviation:drop-unloaded-land-cells", Walks),
        new("§7 #5", "numSphere == 0 works on a copy", null, null, null, "unobservable through the contract: positions are passed by value (ICellPhysics, protocol v1), so no caller Position can be mutated"),
        new("§8", "test vectors", null, null, null, "fixed vectors, pinned by goldens (props/Core/AdjustToOutsideGoldens, props/Outdoor/OutdoorGoldens), not by generated cases"),
    ];
}
