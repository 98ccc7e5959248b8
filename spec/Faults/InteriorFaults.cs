using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// Issue 41: planted faults where ports really differ indoors — a comparison taken non-strictly at its exact bound in
/// the cell's frame (facts §5.1, §5.7: every retail transit comparison is false at the tie), and interiors side by side
/// (facts §5.3: every walked land cell's building is asked, not only the one under the body).
/// </summary>
public static class InteriorFaults
{
    /// <summary>The BSP sphere test's bound taken strictly.</summary>
    public static readonly PlantedFault BspBoundStrict = new(
        "bsp-bound-strict",
        "sphere_intersects_cell says Outside only when d < −(r + 0.01) (strict), so a sphere exactly at the bound enters",
        "facts §5.7 (BN:219-240): d ≤ −R is Outside; a port wrote `if (d < -R) return Outside`, so a portal neighbour or a building's room exactly r + 0.01 away in its own frame becomes a candidate.",
        ["TIES-PINNED-INDOOR"]);

    /// <summary>The exit straddle taken inclusively.</summary>
    public static readonly PlantedFault ExitStraddleInclusive = new(
        "exit-straddle-inclusive",
        "the exit-portal straddle test is inclusive (−R ≤ d ≤ R)",
        "facts §5.1 (EC:311-371): −R < d < R, both strict, R = r + EPS; a port wrote `Math.Abs(d) <= R`, so a sphere exactly r + EPS from an exit plane adds the outdoor cells.",
        ["TIES-PINNED-INDOOR"]);

    /// <summary>The load-hint side test taken inclusively.</summary>
    public static readonly PlantedFault HintBoundInclusive = new(
        "hint-bound-inclusive",
        "the load-hint side test is inclusive (PortalSide d ≥ −R, else d ≤ R)",
        "facts §5.1, §5.4: PortalSide and d > −R, or !PortalSide and d < R (R = r + EPS); a port wrote `>=`/`<=`, so a hint is added for a sphere exactly at the bound.",
        ["TIES-PINNED-INDOOR"]);

    /// <summary>Building entry asks only the centre's land cell.</summary>
    public static readonly PlantedFault BuildingCentreCellOnly = new(
        "building-centre-cell-only",
        "building entry asks only the building of the land cell under sphere 0's centre, not of every walked land cell",
        "facts §5.3, §4 step 4a: LandCell.find_transit_cells runs for every land cell in the array and asks its SortCell's building; a port asked the building \"the body is in\", so leaving one house through its door while touching the neighbouring house (attached to the next land cell) misses the neighbour's room.",
        ["BUILDING-ENTRY-COMPLETE", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Building entry asked only when the query starts outdoors.</summary>
    public static readonly PlantedFault BuildingEntryOutdoorsOnly = new(
        "building-entry-outdoors-only",
        "building entry is asked only when the position is outdoors: a body leaving one building through its door never enters the next",
        "facts §5.3, §4 step 4a: the closure asks the building of every land cell in the array, also of land cells added through an exit portal of the building the body is in; a port reasoned \"indoors, we are already in a building\" and skipped it, so leaving one house through its door while touching the neighbour's room (row houses, doors a body-width apart) misses that room.",
        ["BUILDING-ENTRY-COMPLETE", "FIND-CELL-CONFORMANCE"]);

    /// <summary>From indoors, building entry asks only the body's own building.</summary>
    public static readonly PlantedFault BuildingEntryOwnBuildingOnly = new(
        "building-entry-own-building-only",
        "from indoors, building entry asks only the building the body is in: leaving one house through its door while touching the next house's room never enters that room",
        "facts §4 step 4a, §5.3: every land cell in the array asks its own SortCell's building, whoever's rooms the position is in; a port reasoned \"a body inside a building can only re-enter its own building through a door\" and, for an indoor position, skipped every other building (its own building's sealed closet is still entered; doors a body-width apart or row houses sharing a wall are not).",
        ["BUILDING-ENTRY-COMPLETE", "FIND-CELL-CONFORMANCE"]);

    /// <summary>Gets every fault of this list.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [BspBoundStrict, ExitStraddleInclusive, HintBoundInclusive, BuildingCentreCellOnly, BuildingEntryOutdoorsOnly, BuildingEntryOwnBuildingOnly];

    /// <summary>Returns the code defect a fault of this list plants (none for another fault or a volume fault).</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The defect.</returns>
    internal static IndoorDefect DefectOf(PlantedFault fault) => fault.Id switch
    {
        "exit-straddle-inclusive" => IndoorDefect.ExitStraddleInclusive,
        "hint-bound-inclusive" => IndoorDefect.HintBoundInclusive,
        "building-centre-cell-only" => IndoorDefect.BuildingCentreCellOnly,
        "building-entry-outdoors-only" => IndoorDefect.BuildingEntryOutdoorsOnly,
        "building-entry-own-building-only" => IndoorDefect.BuildingOwnBuildingIndoors,
        _ => IndoorDefect.None,
    };

    /// <summary>Returns the volume decorator a fault of this list plants, or null.</summary>
    /// <param name="fault">The fault.</param>
    /// <returns>The decorator, or null.</returns>
    internal static Func<ICellVolume, IReadOnlyList<ConvexPiece>, ICellVolume>? VolumeOf(PlantedFault fault) => fault.Id switch
    {
        "bsp-bound-strict" => (v, pieces) => new ChainSphereVolume(v, pieces[0], ChainSphereVolume.StrictBound),
        _ => null,
    };

    /// <summary>Whether building entry asks a walked land cell's building (retail: always, facts §5.3).</summary>
    /// <param name="scene">The scene.</param>
    /// <param name="land">The walked land cell.</param>
    /// <param name="building">Its building.</param>
    /// <param name="position">The position's cell.</param>
    /// <param name="spheres">Centres in the position's block frame.</param>
    /// <param name="defect">The defect.</param>
    /// <returns>False when the defect skips it.</returns>
    internal static bool AsksBuilding(IScene scene, CellId land, Building building, CellId position, ReadOnlySpan<Sphere> spheres, IndoorDefect defect)
    {
        if (defect == IndoorDefect.BuildingEntryOutdoorsOnly)
        {
            return !position.IsIndoorByLowWord;
        }

        if (defect == IndoorDefect.BuildingOwnBuildingIndoors)
        {
            return !position.IsIndoorByLowWord || Rooms(scene, land, building).Contains(position);
        }

        if (defect != IndoorDefect.BuildingCentreCellOnly || spheres.IsEmpty)
        {
            return true;
        }

        float x = spheres[0].Center.X, y = spheres[0].Center.Y;
        var at = position.IsLand ? position : position.WithLow(1);
        return LandDefs.AdjustToOutside(ref at, ref x, ref y) && at == land;
    }

    // A building's rooms as a port finds them: the cells behind its portals and every cell their cell portals reach.
    private static HashSet<CellId> Rooms(IScene scene, CellId land, Building building)
    {
        var rooms = new HashSet<CellId>();
        var queue = new Queue<CellId>(building.Portals.Select(p => land.WithLow(p.OtherCellId)));
        while (queue.TryDequeue(out var id))
        {
            if (!rooms.Add(id) || scene.GetEnvCell(id) is not { } env)
            {
                continue;
            }

            foreach (var portal in env.Portals)
            {
                if (portal.OtherCellId != CellPortal.Outside)
                {
                    queue.Enqueue(id.WithLow(portal.OtherCellId));
                }
            }
        }

        return rooms;
    }
}
