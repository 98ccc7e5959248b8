using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>Invariants of one outdoor query (facts §3–§4): coverage, soundness, frame symmetry, translation, sphere order, pick.</summary>
public static class OutdoorInvariants
{
    /// <summary>How deep a disc must reach into a square before COVERAGE demands the cell, metres.</summary>
    public const double Tolerance = 1e-3;

    /// <summary>COVERAGE.</summary>
    public static readonly Invariant<OutdoorCase> Coverage = new(
        "COVERAGE",
        "Every on-map land cell of the 3 × 3 neighbourhood of a sphere's centre cell (the cell after the EPS snap) whose square the sphere's disc overlaps by more than 1 mm is in the set (spheres up to the first one whose centre is off the map).",
        "facts §3.2, §3.3",
        Op.OutsideCells,
        OutdoorDomain.Instance,
        (impl, c) =>
        {
            var set = impl.OutsideCells(c.Cell, c.Origin, c.Spheres).ToHashSet();
            if (!PositionValid(c.Cell))
            {
                return Outcome.Vacuous; // retail's AdjustToOutside fails on the position's id itself: no sphere adds a cell
            }

            bool applied = false;
            foreach (var s in c.Spheres)
            {
                if (!OnMap(c.Cell, s.Center))
                {
                    break;
                }

                applied = true;
                var (gx, gy) = CentreLcoord(c.Cell, s.Center);
                for (int dx = -1; dx <= 1; dx++)
                {
                    for (int dy = -1; dy <= 1; dy++)
                    {
                        long nx = gx + dx, ny = gy + dy;
                        if (!Oracle.OnMap(nx, ny))
                        {
                            continue;
                        }

                        var id = Oracle.CellOf((int)nx, (int)ny);
                        var (gapX, gapY) = Gap(c.Cell, id, s.Center);
                        double d = Math.Sqrt((gapX * gapX) + (gapY * gapY));
                        if (d < s.Radius - Tolerance && !set.Contains(id))
                        {
                            return Outcome.Violated($"{id} is {d:R} m from the centre of sphere r={s.Radius:R} but missing from [{string.Join(", ", set)}]");
                        }
                    }
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        });

    /// <summary>SOUNDNESS.</summary>
    public static readonly Invariant<OutdoorCase> Soundness = new(
        "SOUNDNESS",
        "Every cell in the set is an on-map land cell whose square lies within radius + 1 mm of a sphere centre per axis (the boundary test is a square, not a circle, facts §3.2), and no cell appears twice.",
        "facts §3.2, §5.9",
        Op.OutsideCells,
        OutdoorDomain.Instance,
        (impl, c) =>
        {
            var cells = impl.OutsideCells(c.Cell, c.Origin, c.Spheres);
            if (cells.Distinct().Count() != cells.Count)
            {
                return Outcome.Violated($"duplicate ids in [{string.Join(", ", cells)}]");
            }

            foreach (var id in cells)
            {
                if (!Oracle.IsLandCellOnMap(id))
                {
                    return Outcome.Violated($"{id} is not a land cell on the map");
                }

                // With no spheres the position's own point stands in (facts §3.3 step 3). A cell from a non-finite centre
                // is judged by NONFINITE-SPHERE-ENDS-LOOP, a hardening rule (retail would add its block's column, §6.17).
                if (Conformance.HasNonFiniteCentre(c.Spheres))
                {
                    continue;
                }

                bool near = (c.Spheres.Count == 0 ? [new Sphere(c.Origin, 0)] : c.Spheres).Any(s =>
                {
                    var (gapX, gapY) = Gap(c.Cell, id, s.Center);
                    return Math.Max(gapX, gapY) <= s.Radius + Tolerance;
                });
                if (!near)
                {
                    return Outcome.Violated($"{id} is farther than r + 1 mm from every sphere");
                }
            }

            return cells.Count > 0 ? Outcome.Holds : Outcome.Vacuous;
        });

    /// <summary>NEIGHBOUR-SYMMETRY.</summary>
    public static readonly Invariant<OutdoorCase> NeighbourSymmetry = new(
        "NEIGHBOUR-SYMMETRY",
        "The set for a world sphere is the same whichever adjacent landblock's frame expresses it (re-expressed exactly, by whole blocks), except where a centre falls in the EPS snap band 0 < |v| < 0.0002 of a block line in one frame, which retail snaps to the line, or an inexact float32 re-base rounds it onto one (facts §2.1, docs/numerics.md).",
        "facts §1.3, §6.1, seed #106",
        Op.OutsideCells,
        OutdoorDomain.Instance,
        (impl, c) =>
        {
            var baseline = impl.OutsideCells(c.Cell, c.Origin, c.Spheres).ToHashSet();
            if (c.Spheres.Count == 0 || !PositionValid(c.Cell))
            {
                return Outcome.Vacuous; // only spheres are re-expressed; an invalid id has no frame to re-express
            }

            bool applied = false;
            for (int dbx = -1; dbx <= 1; dbx++)
            {
                for (int dby = -1; dby <= 1; dby++)
                {
                    int bx = c.Cell.BlockX + dbx, by = c.Cell.BlockY + dby;
                    if ((dbx == 0 && dby == 0) || bx is < 0 or > 0xFE || by is < 0 or > 0xFE)
                    {
                        continue;
                    }

                    if (!TryShift(c.Spheres, new Vector3(-192f * dbx, -192f * dby, 0), out var moved))
                    {
                        continue;
                    }

                    applied = true;
                    var other = impl.OutsideCells(new CellId((byte)bx, (byte)by, 1), moved).ToHashSet();
                    if (!other.SetEquals(baseline))
                    {
                        return Outcome.Violated($"from block {new LandblockId((byte)bx, (byte)by)}: [{string.Join(", ", other.Order())}] vs [{string.Join(", ", baseline.Order())}]");
                    }
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        });

    /// <summary>TRANSLATION.</summary>
    public static readonly Invariant<OutdoorCase> Translation = new(
        "TRANSLATION",
        "Shifting every sphere by whole cells or whole blocks shifts the set by the same lcoords, away from the map edges, outside the EPS snap band 0 < |v| < 0.0002 of a block line and where every float32 re-base is exact (facts §2.1, docs/numerics.md).",
        "facts §1.3, §3",
        Op.OutsideCells,
        OutdoorDomain.Instance,
        (impl, c) =>
        {
            var baseline = impl.OutsideCells(c.Cell, c.Origin, c.Spheres);
            if (c.Spheres.Count == 0 || !PositionValid(c.Cell))
            {
                return Outcome.Vacuous;
            }

            bool applied = false;
            foreach (var (kx, ky) in new[] { (1, 0), (0, -1), (-3, 2), (8, 0), (-8, 8), (17, -9) })
            {
                if (!AwayFromEdge(c, kx, ky) || !TryShift(c.Spheres, new Vector3(24f * kx, 24f * ky, 0), out var moved))
                {
                    continue;
                }

                applied = true;
                var expected = baseline.Select(id => Shift(id, kx, ky)).ToHashSet();
                var got = impl.OutsideCells(c.Cell, moved).ToHashSet();
                if (!got.SetEquals(expected))
                {
                    return Outcome.Violated($"shift ({kx}, {ky}) cells: got [{string.Join(", ", got.Order())}], expected [{string.Join(", ", expected.Order())}]");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        });

    /// <summary>SPHERE-ORDER.</summary>
    public static readonly Invariant<OutdoorCase> SphereOrder = new(
        "SPHERE-ORDER",
        "The set, as a set, does not depend on the order of the spheres, when every centre is on the map (an off-map centre ends the sphere loop, facts §3.3 b).",
        "facts §3.3",
        Op.OutsideCells,
        OutdoorDomain.Instance,
        (impl, c) =>
        {
            if (c.Spheres.Count < 2 || !c.Spheres.All(s => OnMap(c.Cell, s.Center)))
            {
                return Outcome.Vacuous;
            }

            var baseline = impl.OutsideCells(c.Cell, c.Origin, c.Spheres).ToHashSet();
            var reversed = impl.OutsideCells(c.Cell, c.Origin, c.Spheres.Reverse().ToArray()).ToHashSet();
            var rotated = impl.OutsideCells(c.Cell, c.Origin, [.. c.Spheres.Skip(1), c.Spheres[0]]).ToHashSet();
            return reversed.SetEquals(baseline) && rotated.SetEquals(baseline)
                ? Outcome.Holds
                : Outcome.Violated($"[{string.Join(", ", baseline.Order())}] vs reversed [{string.Join(", ", reversed.Order())}] vs rotated [{string.Join(", ", rotated.Order())}]");
        });

    /// <summary>STABLE-PICK.</summary>
    public static readonly Invariant<OutdoorCase> StablePick = new(
        "STABLE-PICK",
        "With the retail pick, the containing cell depends on the position alone: it is the same whatever current cell is passed, and its closed square contains sphere 0's centre (within the 1 mm tie band: retail re-expresses the centre in float32).",
        "facts §4 step 4b, §5.5",
        Op.FindCell,
        OutdoorDomain.Instance,
        (impl, c) =>
        {
            if (c.Spheres.Count == 0)
            {
                return Outcome.Vacuous;
            }

            var first = impl.FindCell(c.Cell, c.Origin, c.Spheres, CellId.None);
            foreach (var current in first.Cells.Take(4))
            {
                var again = impl.FindCell(c.Cell, c.Origin, c.Spheres, current);
                if (again.Containing != first.Containing)
                {
                    return Outcome.Violated($"pick {again.Containing} with current {current}, {first.Containing} with none");
                }
            }

            if (!first.Containing.IsNone && !NearSquare(c.Cell, first.Containing, c.Spheres[0].Center, Tolerance))
            {
                return Outcome.Violated($"pick {first.Containing} does not contain sphere 0's centre");
            }

            return Outcome.Holds;
        },
        PickPolicy.Retail);

    /// <summary>HYSTERESIS.</summary>
    public static readonly Invariant<OutdoorCase> Hysteresis = new(
        "HYSTERESIS",
        "With the current-cell-first pick, a current cell that is a candidate and still contains sphere 0's centre is kept.",
        "issue #3 (acdream's pick policy), facts §4",
        Op.FindCell,
        OutdoorDomain.Instance,
        (impl, c) =>
        {
            if (c.Spheres.Count == 0)
            {
                return Outcome.Vacuous;
            }

            var first = impl.FindCell(c.Cell, c.Origin, c.Spheres, CellId.None);
            bool applied = false;
            foreach (var current in first.Cells.Where(id => id.IsLand && SquareContains(c.Cell, id, c.Spheres[0].Center)))
            {
                applied = true;
                var again = impl.FindCell(c.Cell, c.Origin, c.Spheres, current);
                if (again.Containing != current)
                {
                    return Outcome.Violated($"current {current} still contains the centre but the pick moved to {again.Containing}");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        },
        PickPolicy.CurrentFirst);

    /// <summary>NONFINITE-SPHERE-ENDS-LOOP.</summary>
    public static readonly Invariant<OutdoorCase> NonFiniteSphereEndsLoop = new(
        "NONFINITE-SPHERE-ENDS-LOOP",
        "A sphere whose centre has a NaN or infinite x or y adds no cell and ends the sphere loop, as an off-map centre does: outside_cells answers exactly what it answers for the spheres before it, without an exception (a hardening rule: retail most likely re-seats it in its block's own column, facts §6.17).",
        "facts §3.3 b, §6.17 (hardening)",
        Op.OutsideCells,
        OutdoorDomain.Instance,
        (impl, c) =>
        {
            int k = -1;
            for (int i = 0; i < c.Spheres.Count && k < 0; i++)
            {
                k = float.IsFinite(c.Spheres[i].Center.X) && float.IsFinite(c.Spheres[i].Center.Y) ? -1 : i;
            }

            if (k < 0)
            {
                return Outcome.Vacuous;
            }

            var got = impl.OutsideCells(c.Cell, c.Origin, c.Spheres);
            var before = k == 0 ? [] : impl.OutsideCells(c.Cell, c.Origin, c.Spheres.Take(k).ToArray());
            return got.SequenceEqual(before)
                ? Outcome.Holds
                : Outcome.Violated($"sphere {k} ({OutdoorCase.Format(c.Spheres[k])}) is not finite, yet the cells are [{string.Join(", ", got)}] where the {k} sphere(s) before it give [{string.Join(", ", before)}]");
        });

    /// <summary>Gets every outdoor-query invariant.</summary>
    public static IReadOnlyList<Invariant<OutdoorCase>> All { get; } = [Coverage, Soundness, NeighbourSymmetry, Translation, SphereOrder, StablePick, Hysteresis, NonFiniteSphereEndsLoop];

    /// <summary>Tests whether AdjustToOutside accepts the position's id at all: a valid low word and an on-map block (facts §2.1 step 1, §2 get_outside_lcoord).</summary>
    /// <param name="cell">The position's id.</param>
    /// <returns>True when a sphere can add cells.</returns>
    public static bool PositionValid(CellId cell) => Oracle.LowInRange(cell.Low) && Oracle.BlockOnMap(cell);

    /// <summary>Returns a block-frame point in world metres (double; exact for the magnitudes generated).</summary>
    /// <param name="frame">The cell whose block frame the point is in.</param>
    /// <param name="p">The point.</param>
    /// <returns>World (x, y).</returns>
    public static (double X, double Y) World(CellId frame, Vector3 p) => ((192.0 * frame.BlockX) + p.X, (192.0 * frame.BlockY) + p.Y);

    /// <summary>Tests whether a frame point lies on the map, exactly (integer bounds in the frame).</summary>
    /// <param name="frame">The frame's cell.</param>
    /// <param name="p">The point.</param>
    /// <returns>True when on the map.</returns>
    public static bool OnMap(CellId frame, Vector3 p)
    {
        double bx = 192.0 * frame.BlockX, by = 192.0 * frame.BlockY, map = 24.0 * Oracle.MapCells;
        return p.X >= -bx && p.X < map - bx && p.Y >= -by && p.Y < map - by;
    }

    /// <summary>Tests whether a land cell's closed square contains a frame point, exactly (the square's edges are integers in the frame).</summary>
    /// <param name="frame">The frame's cell.</param>
    /// <param name="cell">A land cell.</param>
    /// <param name="p">The point.</param>
    /// <returns>True when inside or on the square.</returns>
    public static bool SquareContains(CellId frame, CellId cell, Vector3 p)
    {
        var (west, south) = SquareOrigin(frame, cell);
        return p.X >= west && p.X <= west + 24 && p.Y >= south && p.Y <= south + 24;
    }

    /// <summary>Tests whether a coordinate lies in the EPS snap band, where AdjustToOutside moves it to 0 (facts §2.1): 0 &lt; |v| &lt; EPS.</summary>
    /// <param name="v">A block-frame coordinate.</param>
    /// <returns>True when AdjustToOutside would snap it across a block line.</returns>
    public static bool InSnapBand(float v) => v != 0 && Math.Abs(v) < LandDefs.Epsilon;

    /// <summary>Tests whether a sphere's centre sits where retail's float32 cell math depends on the frame: the snap band or an inexact re-base.</summary>
    /// <param name="s">The sphere.</param>
    /// <returns>True when frame-dependent.</returns>
    public static bool FrameSensitive(Sphere s) =>
        InSnapBand(s.Center.X) || InSnapBand(s.Center.Y) || !Oracle.RebaseIsExact(s.Center.X) || !Oracle.RebaseIsExact(s.Center.Y);

    /// <summary>Tests whether a frame point is within a margin of a land cell's square (per axis, exact).</summary>
    /// <param name="frame">The frame's cell.</param>
    /// <param name="cell">A land cell.</param>
    /// <param name="p">The point.</param>
    /// <param name="margin">Metres.</param>
    /// <returns>True when within the margin.</returns>
    public static bool NearSquare(CellId frame, CellId cell, Vector3 p, double margin)
    {
        var (dx, dy) = Gap(frame, cell, p);
        return Math.Max(dx, dy) <= margin;
    }

    // Shifts every centre; false when a shifted centre is not exact (it would not be the same world point) or when
    // either version sits where retail's float32 cell math depends on the frame (FrameSensitive).
    private static bool TryShift(IReadOnlyList<Sphere> spheres, Vector3 shift, out Sphere[] moved)
    {
        moved = spheres.Select(s => s with { Center = s.Center + shift }).ToArray();
        for (int i = 0; i < moved.Length; i++)
        {
            if (moved[i].Center - shift != spheres[i].Center || FrameSensitive(moved[i]) || FrameSensitive(spheres[i]))
            {
                return false;
            }
        }

        return true;
    }

    private static (double West, double South) SquareOrigin(CellId frame, CellId cell)
    {
        var (gx, gy) = Oracle.LcoordOf(cell);
        return ((24.0 * gx) - (192.0 * frame.BlockX), (24.0 * gy) - (192.0 * frame.BlockY));
    }

    private static (long X, long Y) CentreLcoord(CellId frame, Vector3 p) =>
        ((8L * frame.BlockX) + (long)Math.Floor(Oracle.Snap(p.X) / 24.0), (8L * frame.BlockY) + (long)Math.Floor(Oracle.Snap(p.Y) / 24.0));

    private static (double Dx, double Dy) Gap(CellId frame, CellId cell, Vector3 p)
    {
        var (west, south) = SquareOrigin(frame, cell);
        return (Math.Max(Math.Max(west - p.X, p.X - (west + 24)), 0), Math.Max(Math.Max(south - p.Y, p.Y - (south + 24)), 0));
    }

    private static CellId Shift(CellId id, int kx, int ky)
    {
        var (gx, gy) = Oracle.LcoordOf(id);
        return Oracle.CellOf(gx + kx, gy + ky);
    }

    private static bool AwayFromEdge(OutdoorCase c, int kx, int ky) => c.Spheres.All(s =>
    {
        var (wx, wy) = World(c.Cell, s.Center);
        double lo = 48, hi = (24.0 * Oracle.MapCells) - 48;
        return Math.Min(wx, wx + (24.0 * kx)) >= lo && Math.Max(wx, wx + (24.0 * kx)) < hi
            && Math.Min(wy, wy + (24.0 * ky)) >= lo && Math.Max(wy, wy + (24.0 * ky)) < hi;
    });
}
