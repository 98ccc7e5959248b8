using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

// Load hints for unloaded cells behind a portal (facts §4 step 3, §5.1).
internal static partial class IndoorInvariants
{
    // The position's own portals into unloaded cells, the side read from the geometry (the cell's box centre), not from
    // PortalSide. A sphere reaching past one by r + EPS gives the hint: the position is walked first (facts §4 step 3,
    // §5.1). A hint given while no sphere reaches it is wrong only if no other cell the closure may walk gives it either:
    // the transit closure walks every cell it adds, and any of them with a portal to the same unloaded cell adds the
    // same hint when a sphere reaches that portal's infinite plane (facts §4 step 4a, §5.1). Which cells were walked is
    // over-approximated by the loaded env cells of the block within r + 0.01 + 1 mm of a sphere (a neighbour or a
    // building's cell is added only when the BSP sphere test, padded 0.01, takes it in: §5.1, §5.3, §5.7; the filter
    // may drop a walked cell after its hint was added, and never drops a hint, §4 step 5), so this direction never
    // accuses a hint retail gives.
    // Under a declared ace-load-hint-low-key the hint is looked for under ACE's key, the bare 16-bit id (facts §7 #11).
    private static string? LoadHintMismatch(SceneWalk w, WalkStep s, IndoorFidelity fidelity)
    {
        var cell = SceneOracle.Cell(w.Scene, s.Query.Cell);
        if (cell is null || !SceneOracle.IsLoadedEnv(w.Scene, cell.Id))
        {
            return null;
        }

        foreach (var outward in Outward(cell))
        {
            var other = cell.Id.WithLow(outward.Portal.Other);
            if (outward.Portal.IsExit || !w.Scene.UnloadedCells.Contains(other))
            {
                continue;
            }

            var (reaches, tie) = Reach(outward, s);
            bool given = s.Cells.Contains(fidelity.AceLoadHintLowKey ? new CellId(other.Low) : other);
            if (tie || reaches == given)
            {
                continue;
            }

            if (reaches)
            {
                return $"a sphere reaches past the portal of {cell.Id} toward unloaded {other} but no load hint was given";
            }

            if (!HintedElsewhere(w.Scene, cell, other, s))
            {
                return $"load hint {other} given although every sphere is wholly on {cell.Id}'s side of the portal, and no other loaded cell's portal to it is reached";
            }
        }

        return null;
    }

    // Whether another loaded env cell the closure may have walked has a portal to the unloaded cell whose plane a sphere reaches (or ties).
    private static bool HintedElsewhere(Scene scene, SceneCell own, CellId other, WalkStep s) =>
        scene.Cells.Where(c => c.Id != own.Id && c.Id.Landblock == other.Landblock && SceneOracle.IsLoadedEnv(scene, c.Id)
                && s.Query.Spheres.Any(sp => SceneOracle.Depth(c, s.Query.Cell, sp.Center) >= -(sp.Radius + 0.01 + Margin)))
            .Any(c => Outward(c).Any(o => !o.Portal.IsExit && c.Id.WithLow(o.Portal.Other) == other && Reach(o, s) is (true, _) or (_, true)));

    // Whether a sphere reaches past a portal's plane by r + EPS, and whether one is within 1 mm of that (a tie).
    private static (bool Reaches, bool Tie) Reach(OutwardPortal outward, WalkStep s)
    {
        bool reaches = false, tie = false;
        foreach (var sphere in s.Query.Spheres)
        {
            double slack = outward.Past(sphere.Center) + sphere.Radius + LandDefs.Epsilon;
            tie |= Math.Abs(slack) < Margin;
            reaches |= slack > 0;
        }

        return (reaches, tie);
    }
}
