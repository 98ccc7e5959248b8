using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// Issue 41: exact bounds pinned where retail is exact. The conformance invariants excuse a difference a probe 8 ulps
/// away explains (docs/conformance.md, "Numerical ties"), so they cannot tell `&lt;` from `&lt;=` at a tie; this statement
/// can, where the tie is no rounding at all: the tested cell's frame, the plane and the centre give the same distance in
/// float32 (after GlobalToLocal, as retail computes it) and in double, and it equals the bound R = r + pad rounded once
/// to float32 (facts §1.5: R is a float32 sum in retail), and a port that computes R in double (r + 0.01, r + 0.0002)
/// decides the tie the same way (found: the Python example, which computes in double, entered a neighbour at a
/// near-touch tie whose exact sum r + 0.01 is above the float32 R).
/// </summary>
public static class IndoorTieInvariants
{
    /// <summary>TIES-PINNED-INDOOR.</summary>
    public static readonly Invariant<SceneWalk> TiesPinned = new(
        "TIES-PINNED-INDOOR",
        "At an exact bound (the same distance in float32 after GlobalToLocal and in double, equal to R = r + pad in float32, and R in double, r + 0.01 or r + 0.0002, not above it, so double arithmetic decides it alike) retail's comparison is false: a loaded env cell every sphere is at d = −(r + 0.01) from (BSP test: Outside) or clear of by more than 1 mm is no candidate unless it is the position; with no filter, a transition from an env position adds no land cell when every sphere is at |d| = r + EPS from every exit plane of the walked env candidates or clear of straddling it by more than 1 mm, and no load hint for a cell every sphere is at the side test's bound or clear of by more than 1 mm.",
        "facts §1.5, §5.1, §5.3, §5.4, §5.7, §6.10",
        Op.None,
        SceneDomain.Instance,
        (impl, w) => ExactSteps.EachStep(impl, w, (scene, s) => Check(impl, scene, s)), sceneForms: SceneQueryKinds.Either);

    /// <summary>Gets this list.</summary>
    public static IReadOnlyList<Invariant<SceneWalk>> All { get; } = [TiesPinned];

    private enum Side
    {
        Neither,
        Clear,
        Tie,
    }

    private static Outcome Check(ICellPhysics impl, ExactScene scene, WalkStep s)
    {
        var position = s.Query.Cell;
        if (!scene.ClosureRuns(position, s.Query.Spheres.Count))
        {
            return Outcome.Vacuous;
        }

        bool tied = false;
        for (int i = 0; i < s.Cells.Count; i++)
        {
            var id = s.Cells[i];
            if (id == position || !id.IsEnv || !ExactSteps.IsLoadedEntry(scene, s, i) || scene.Env(id) is not { } cell)
            {
                continue;
            }

            var sides = s.Query.Spheres.Select(sp => Bsp(cell, ExactSteps.TransitPoint(impl, position, id, sp.Center), sp.Radius)).ToList();
            if (sides.All(x => x != Side.Neither) && sides.Contains(Side.Tie))
            {
                return Outcome.Violated($"{id} is a candidate but every sphere is clear of it or exactly at d = −(r + 0.01) from its first piece in its frame, where the BSP test says Outside (facts §5.7: d ≤ −R)");
            }
        }

        if (!ExactSteps.Filtered(s))
        {
            if (Exits(impl, scene, s) is { } exits)
            {
                tied |= exits.Tied;
                var land = s.Cells.Where(x => x.IsLand).ToList();
                if (exits.Tied && exits.AllDecided && land.Count > 0)
                {
                    return Outcome.Violated($"land cells [{string.Join(", ", land)}] are candidates but every sphere is exactly at |d| = r + EPS from the exit planes or clear of straddling them (facts §5.1: −R < d < R, both strict)");
                }
            }

            foreach (var hint in s.Cells.Where(x => x.IsEnv && scene.Env(x) is null))
            {
                var h = Hint(impl, scene, s, hint);
                tied |= h.Tied;
                if (h.Tied && h.AllDecided)
                {
                    return Outcome.Violated($"load hint {hint} is a candidate but every sphere is exactly at the side test's bound or clear of it for every walked portal to it (facts §5.1, §5.4: PortalSide d > −R, else d < R)");
                }
            }
        }

        tied |= scene.Envs.Any(c => c.Source.Id != position && s.Query.Spheres.Any(sp => Bsp(c, ExactSteps.TransitPoint(impl, position, c.Source.Id, sp.Center), sp.Radius) == Side.Tie));
        return tied ? Outcome.Holds : Outcome.Vacuous;
    }

    // The BSP sphere test at its bound: clear when the first piece is more than 1 mm beyond R = r + 0.01, tie when
    // float32 and double both give exactly −R.
    private static Side Bsp(ExactCell cell, Vector3 p, float r)
    {
        float bound = r + 0.01f;
        double d64 = cell.DepthFirst(p);
        if (d64 < -(double)bound - IndoorInvariants.Margin)
        {
            return Side.Clear;
        }

        // A port computing R = r + 0.01 in double must decide it the same way (docs/conformance.md, "Numerical ties").
        return d64 == -(double)bound && bound >= r + 0.01 && Depth32(cell.Source, p) == -bound ? Side.Tie : Side.Neither;
    }

    // Exit straddles of the walked env candidates in a transition from an env position (facts §5.1).
    private static (bool Tied, bool AllDecided)? Exits(ICellPhysics impl, ExactScene scene, WalkStep s)
    {
        if (!s.LoadCells || !s.Query.Cell.IsEnv)
        {
            return null;
        }

        bool tied = false, decided = true;
        foreach (var (cell, k) in Walked(scene, s).SelectMany(c => Enumerable.Range(0, c.Source.Portals.Count).Where(k => c.Source.Portals[k].IsExit).Select(k => (c, k))))
        {
            foreach (var sp in s.Query.Spheres)
            {
                var p = ExactSteps.TransitPoint(impl, s.Query.Cell, cell.Source.Id, sp.Center);
                float bound = sp.Radius + LandDefs.Epsilon;
                double d64 = cell.PortalDistance(k, p);
                if (Math.Abs(d64) > bound + IndoorInvariants.Margin)
                {
                    continue;
                }

                bool tie = Math.Abs(d64) == bound && bound >= sp.Radius + 0.0002 && MathF.Abs(Distance32(cell.Source, k, p)) == bound;
                tied |= tie;
                decided &= tie;
            }
        }

        return (tied, decided);
    }

    // The load-hint side tests of the walked env candidates' portals to an unloaded cell (facts §5.1, §5.4).
    private static (bool Tied, bool AllDecided) Hint(ICellPhysics impl, ExactScene scene, WalkStep s, CellId hint)
    {
        bool tied = false, decided = true, any = false;
        foreach (var cell in Walked(scene, s))
        {
            for (int k = 0; k < cell.Source.Portals.Count; k++)
            {
                var portal = cell.Source.Portals[k];
                if (portal.IsExit || portal.Other != hint.Low || (hint.Landblock != cell.Source.Id.Landblock && !impl.Indoor.AceLoadHintLowKey))
                {
                    continue;
                }

                any = true;
                foreach (var sp in s.Query.Spheres)
                {
                    var p = ExactSteps.TransitPoint(impl, s.Query.Cell, cell.Source.Id, sp.Center);
                    float bound = sp.Radius + LandDefs.Epsilon, sign = portal.PortalSide ? -1 : 1;
                    double d64 = cell.PortalDistance(k, p);
                    if (sign * d64 > bound + IndoorInvariants.Margin)
                    {
                        continue; // clear: PortalSide and d < −R − 1 mm, or the other side and d > R + 1 mm
                    }

                    bool tie = d64 == sign * bound && bound >= sp.Radius + 0.0002 && Distance32(cell.Source, k, p) == sign * bound;
                    tied |= tie;
                    decided &= tie;
                }
            }
        }

        return (tied && any, decided);
    }

    private static IEnumerable<ExactCell> Walked(ExactScene scene, WalkStep s) =>
        s.Cells.Select((id, i) => (id, i)).Where(t => t.id.IsEnv && ExactSteps.IsLoadedEntry(scene, s, t.i)).Select(t => scene.Env(t.id)!);

    // Float32 as retail computes it: GlobalToLocal, then N·p + D.
    private static float Distance32(SceneCell cell, int portal, Vector3 p) => cell.Portals[portal].Plane.Distance(new Frame(cell.Origin, cell.Rotation).GlobalToLocal(p));

    private static float Depth32(SceneCell cell, Vector3 p)
    {
        var l = new Frame(cell.Origin, cell.Rotation).GlobalToLocal(p);
        var piece = cell.Pieces[0];
        if (piece.Box is { } b)
        {
            return MathF.Min(MathF.Min(MathF.Min(l.X - b.Min.X, b.Max.X - l.X), MathF.Min(l.Y - b.Min.Y, b.Max.Y - l.Y)), MathF.Min(l.Z - b.Min.Z, b.Max.Z - l.Z));
        }

        return piece.Planes!.Min(pl => pl.Distance(l));
    }
}
