using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>Invariants of walks: the containing cell keeps up with the body across every line (the #106 class).</summary>
internal static class WalkInvariants
{
    /// <summary>
    /// The tie band, metres: within it of a cell's square, the pick may name that cell (closed squares, last hit
    /// wins, float32 re-basing: facts §4, §6.5, docs/numerics.md). Far wider than the float32 drift of any generated walk.
    /// </summary>
    public const double TieBand = 1e-3;

    /// <summary>NO-BOUNDARY-FREEZE.</summary>
    public static readonly Invariant<Walk> NoBoundaryFreeze = new(
        "NO-BOUNDARY-FREEZE",
        "After every step the containing cell is the land cell under sphere 0's centre, computed independently in double from the world point of the position the client holds (any cell whose square is within the 1 mm tie band on a line); the one retail exception is a radius-0 sphere 0 inside the EPS snap band of a block line, which retail leaves with no containing cell (docs/numerics.md).",
        "facts §4, §6.1, seed #106",
        Op.FindCell,
        WalkDomain.Instance,
        (impl, w) =>
        {
            var offset = w.Body.Count > 0 ? w.Body[0].Offset : Vector3.Zero;
            bool applied = false;
            foreach (var step in WalkRunner.Run(impl, w))
            {
                double x = step.WorldX + offset.X, y = step.WorldY + offset.Y;
                if (!Inside(x, y, TieBand))
                {
                    continue; // off the map or within the tie band of its edge: MAP-EDGE-WALK's business
                }

                if (ZeroRadiusInSnapBand(w, step))
                {
                    continue;
                }

                applied = true;
                if (step.Containing.IsNone || !Oracle.IsLandCellOnMap(step.Containing) || Distance(step.Containing, x, y) > TieBand)
                {
                    long gx = (long)Math.Floor(x / 24), gy = (long)Math.Floor(y / 24);
                    return Outcome.ViolatedAt(
                        step.Index,
                        $"step {step.Index}: containing {step.Containing} but sphere 0's centre is at world ({x:R}, {y:R}) in {Oracle.CellOf((int)gx, (int)gy)}; current stays {step.Current}");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        });

    /// <summary>WALK-REVERSIBLE.</summary>
    public static readonly Invariant<Walk> WalkReversible = new(
        "WALK-REVERSIBLE",
        "With the retail pick, walking a path and then back, step by step, ends in the cell it started in (when the client's float32 position returns exactly to its start world point, and no step leaves a radius-0 sphere 0 in the EPS snap band with no containing cell).",
        "facts §4 (the pick depends on the position alone)",
        Op.FindCell,
        WalkDomain.Instance,
        (impl, w) =>
        {
            if (w.Steps.Count == 0)
            {
                return Outcome.Vacuous;
            }

            var there = w.Steps.ToArray();
            var back = there.Reverse().Select(s => -s).ToArray();
            var trace = WalkRunner.Run(impl, w with { Steps = [.. there, .. back] });
            var first = trace[0];
            var last = trace[^1];
            if (last.WorldX != first.WorldX || last.WorldY != first.WorldY)
            {
                return Outcome.Vacuous; // float32 drift (re-framing far from a block's origin): not the same point
            }

            if (!OnMap(first.WorldX, first.WorldY) || first.Containing.IsNone || trace.Any(t => ZeroRadiusInSnapBand(w, t)))
            {
                return Outcome.Vacuous;
            }

            return last.Current == first.Current
                ? Outcome.Holds
                : Outcome.Violated($"started in {first.Current}, came back to the same point in {last.Current} (path of {there.Length} steps)");
        },
        PickPolicy.Retail);

    /// <summary>MAP-EDGE-WALK.</summary>
    public static readonly Invariant<Walk> MapEdgeWalk = new(
        "MAP-EDGE-WALK",
        "Walks along and off the map edge never produce a cell id outside the map (every candidate and every pick is a land cell on the map) and never throw.",
        "facts §6.3",
        Op.FindCell,
        WalkDomain.Instance,
        (impl, w) =>
        {
            foreach (var step in WalkRunner.Run(impl, w))
            {
                foreach (var id in step.Cells)
                {
                    if (!Oracle.IsLandCellOnMap(id))
                    {
                        return Outcome.ViolatedAt(step.Index, $"step {step.Index}: candidate {id} is not a land cell on the map");
                    }
                }

                if (!step.Containing.IsNone && !Oracle.IsLandCellOnMap(step.Containing))
                {
                    return Outcome.ViolatedAt(step.Index, $"step {step.Index}: containing {step.Containing} is not a land cell on the map");
                }
            }

            return Outcome.Holds;
        });

    /// <summary>Gets every walk invariant.</summary>
    public static IReadOnlyList<Invariant<Walk>> All { get; } = [NoBoundaryFreeze, WalkReversible, MapEdgeWalk];

    // Retail snaps the candidate (AdjustToOutside) but tests the unsnapped centre in the pick; with r = 0 no neighbour
    // is added, so a centre in (−EPS, 0) of a block line is contained by no candidate (facts §2.1, §3.2, §4).
    private static bool ZeroRadiusInSnapBand(Walk w, WalkStep step) =>
        w.Body.Count > 0 && w.Body[0].Radius == 0 && step.Query.Spheres.Count > 0
        && (OutdoorInvariants.InSnapBand(step.Query.Spheres[0].Center.X) || OutdoorInvariants.InSnapBand(step.Query.Spheres[0].Center.Y));

    private static bool OnMap(double x, double y) => x >= 0 && y >= 0 && x < 24.0 * Oracle.MapCells && y < 24.0 * Oracle.MapCells;

    private static bool Inside(double x, double y, double margin) =>
        x >= margin && y >= margin && x < (24.0 * Oracle.MapCells) - margin && y < (24.0 * Oracle.MapCells) - margin;

    private static double Distance(CellId cell, double x, double y)
    {
        var (gx, gy) = Oracle.LcoordOf(cell);
        double dx = Math.Max(Math.Max((24.0 * gx) - x, x - (24.0 * (gx + 1))), 0);
        double dy = Math.Max(Math.Max((24.0 * gy) - y, y - (24.0 * (gy + 1))), 0);
        return Math.Max(dx, dy);
    }
}
