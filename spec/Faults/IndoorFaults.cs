using AcPhys.Contract;

namespace AcPhys.Spec.Faults;

/// <summary>Planted faults of the indoor paths (scenes): each is a defect seen in ports, and each must be caught by the pr profile.</summary>
public static class IndoorFaults
{
    /// <summary>Outdoor cells win the pick.</summary>
    public static readonly PlantedFault OutdoorWins = new(
        "outdoor-wins",
        "the containing pick prefers land cells: the last land hit wins over any env hit",
        "issue #4: a port iterated the candidates with one last-wins rule; standing in a cottage the land cell under it wins, an absorbing outdoor state (facts §4 step 4b: the first env hit wins).",
        ["INTERIOR-WINS", "PORTAL-TRANSIT"]);

    /// <summary>Declares hysteresis for scenes, implements the retail pick.</summary>
    public static readonly PlantedFault NoHysteresisIndoor = new(
        "no-hysteresis-indoor",
        "declares the current-cell-first pick for scenes but implements the retail rule",
        "issue #4: acdream's hysteresis lost in a refactor of the indoor pick; the cell flickers on a shared line next to a building.",
        ["HYSTERESIS-INDOOR"]);

    /// <summary>PortalSide read backwards.</summary>
    public static readonly PlantedFault InvertedPortalSide = new(
        "inverted-portal-side",
        "PortalSide read backwards ((Flags & 2) != 0), as the seed's \"intuition\" paragraph states it",
        "facts §5.4: PortalSide = true puts the owning cell on the negative side; the seed says the opposite, so load hints fire for spheres wholly on the cell's own side and not for spheres reaching the neighbour.",
        ["PORTAL-TRANSIT"]);

    /// <summary>No visibility filter.</summary>
    public static readonly PlantedFault NoVisibilityFilter = new(
        "no-visibility-filter",
        "the indoor VisibleCells filter is skipped although the caller asked for it (LoadCells false)",
        "facts §4 step 5, §6.14: a port that never decides LoadCells per caller keeps every land cell the exit portal added while indoors.",
        ["VISIBILITY"]);

    /// <summary>Candidates of another block tested in the wrong frame.</summary>
    public static readonly PlantedFault NoReframe = new(
        "no-reframe",
        "candidate cells of another landblock are tested with sphere 0's centre still in the position's block frame (no GetBlockOffset)",
        "facts §4 step 4b, §6.11: the transit tests really do skip the block offset, and a port copied that into the containing pick; at a block line the centre is tested ~192 m off and no candidate contains it.",
        ["NEVER-NULL"]);

    /// <summary>The scene array is not reset between calls.</summary>
    public static readonly PlantedFault StaleSceneArray = new(
        "stale-scene-array",
        "find_cell_list keeps earlier calls' cells in its array (ACE's dictionary is never cleared)",
        "facts §4 step 1, §7 #6: ACE resets NumCells but not the Cells dictionary; a Transition's array accumulates stale cells across steps.",
        ["SCENE-SOUNDNESS"]);

    /// <summary>ACE's 16-bit load-hint key.</summary>
    public static readonly PlantedFault AceHintKey = new(
        "ace-hint-key",
        "a load hint is keyed by the bare 16-bit OtherCellId (ACE) instead of the full id",
        "facts §7 #11: ACE adds (OtherCellId, null) with no landblock prefix, so the hint names a cell of block 0x0000 wherever the dungeon is.",
        ["SCENE-TRANSLATION"]);

    /// <summary>A miss answered with the current cell.</summary>
    public static readonly PlantedFault KeepCurrentOnMiss = new(
        "keep-current-on-miss",
        "when no candidate contains sphere 0's centre the query answers the current cell instead of none",
        "issue #4: a port papered over \"a null current cell after a portal\" by falling back to the current cell; the answer then names a cell the body has left (facts §4: currCell stays null).",
        ["CONTAINING-CONTAINS"]);

    /// <summary>Exit portals ignored.</summary>
    public static readonly PlantedFault NoExitTransit = new(
        "no-exit-transit",
        "an env cell's exit portals (OtherCellId 0xFFFF) are skipped, so the outdoor cells are never added from indoors",
        "issue #4: a port handled only cell-to-cell portals in find_transit_cells; a body walks out of the door and keeps the room's id (an absorbing indoor state, facts §5.1).",
        ["ENTER-EXIT", "PORTAL-TRANSIT"]);

    /// <summary>Gets every indoor fault, a port's transit faults (<see cref="IndoorPortFaults"/>) included.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [OutdoorWins, NoHysteresisIndoor, InvertedPortalSide, NoVisibilityFilter, NoReframe, StaleSceneArray, AceHintKey, KeepCurrentOnMiss, NoExitTransit, .. IndoorPortFaults.All];

    /// <summary>Returns an adapter carrying an indoor fault, or null for another fault.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The adapter, or null.</returns>
    public static ICellPhysics? Create(PlantedFault fault) => All.Contains(fault) ? new IndoorFaultyPhysics(fault) : null;
}
