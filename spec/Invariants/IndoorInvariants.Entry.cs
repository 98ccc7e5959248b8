using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Invariants;

// Which cells one query can enter: from land through a building's portals and the transit closure, and portal links (facts §4 step 4a, §5.3).
internal static partial class IndoorInvariants
{
    // The land cells owning a building from whose portals the target is reachable through cell portals.
    private static IEnumerable<CellId> OwnersReaching(Scene scene, CellId target) =>
        scene.Buildings.Where(b => Reaches(scene, b, target)).Select(b => new Building(b.Block, b.Origin, []).OwningCell()).Where(o => !o.IsNone);

    // The env cells a building's portals lead to, and every cell portal-linked to them (the transit closure).
    private static bool Reaches(Scene scene, SceneBuilding building, CellId target)
    {
        var seen = new HashSet<CellId>(building.Portals.Select(p => building.Block.BlockCell.WithLow(p.Cell)));
        var queue = new Queue<CellId>(seen);
        while (queue.Count > 0)
        {
            var id = queue.Dequeue();
            if (id == target)
            {
                return true;
            }

            foreach (var p in SceneOracle.Cell(scene, id)?.Portals ?? [])
            {
                if (!p.IsExit && seen.Add(id.WithLow(p.Other)))
                {
                    queue.Enqueue(id.WithLow(p.Other));
                }
            }
        }

        return false;
    }

    // Facts §5.3: a building portal with the invalid marker (portal 0xFFFF) is skipped, so it leads nowhere.
    private static bool BehindBuildingPortal(Scene scene, CellId cell) =>
        scene.Buildings.Any(b => b.Block == cell.Landblock && b.Portals.Any(p => p.Cell == cell.Low && p.Portal != BldPortal.None));

    private static bool Linked(Scene scene, CellId a, CellId b)
    {
        if (a.IsLand && b.IsLand)
        {
            var (ax, ay) = Oracle.LcoordOf(a);
            var (bx, by) = Oracle.LcoordOf(b);
            return Math.Abs(ax - bx) <= 1 && Math.Abs(ay - by) <= 1;
        }

        if (a.IsEnv && b.IsLand)
        {
            // Facts §4 step 4a: the closure runs within one query, so a step may cross two portals (a thin doorway
            // cell, 0.25 m, between a room and the exit): an exit of the cell or of a portal neighbour will do.
            return Neighbourhood(scene, a).Any(id => SceneOracle.Cell(scene, id) is { } cell && cell.Portals.Any(p => p.IsExit));
        }

        if (a.IsLand && b.IsEnv)
        {
            // facts §4 step 3: the transit closure runs within one query, so a sphere that crosses a wall into a
            // second room is entered through the first room's portals in the same call.
            return scene.Buildings.Any(bl => bl.Block == b.Landblock && Reaches(scene, bl, b));
        }

        // Facts §4 step 4a: two portals in one query (through a thin cell) — b a neighbour of a or of a neighbour of a.
        return a.Landblock == b.Landblock && Neighbourhood(scene, a).Any(m => m != a && (m == b || PortalLinked(scene, m, b)));
    }

    private static bool PortalLinked(Scene scene, CellId a, CellId b) =>
        a.Landblock == b.Landblock
        && ((SceneOracle.Cell(scene, a)?.Portals.Any(p => p.Other == b.Low) ?? false) || (SceneOracle.Cell(scene, b)?.Portals.Any(p => p.Other == a.Low) ?? false));

    // An env cell and the cells portal-linked to it.
    private static IEnumerable<CellId> Neighbourhood(Scene scene, CellId a) =>
        scene.Cells.Where(c => c.Id == a || PortalLinked(scene, a, c.Id)).Select(c => c.Id).Append(a).Distinct();
}
