using System.Numerics;
using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>Invariants of the parts / bounding-box variant (facts §3.4), against an exact hull computed in double.</summary>
internal static class PartsInvariants
{
    /// <summary>Tolerance, metres: overlaps thinner than this are not required, cells this close to the range are allowed.</summary>
    public const double Tolerance = 1e-3;

    /// <summary>PARTS-COVERAGE.</summary>
    public static readonly Invariant<PartsCase> PartsCoverage = new(
        "PARTS-COVERAGE",
        "Every on-map land cell that a part's box (its 8 transformed corners' hull, or an Always2D part's ±r square) overlaps by more than 1 mm, and the anchor part's own cell, is in the set — across block lines too (retail has no same-block guard).",
        "facts §3.4, §7 #3",
        Op.OutsideCellsParts,
        PartsDomain.Instance,
        (impl, c) =>
        {
            if (Range(c) is not { } range)
            {
                return Outcome.Vacuous;
            }

            var set = impl.OutsideCellsParts(c.Parts).ToHashSet();
            var anchorCell = Oracle.CellOf(range.AnchorX, range.AnchorY);
            if (!set.Contains(anchorCell))
            {
                return Outcome.Violated($"the anchor's cell {anchorCell} is missing from [{string.Join(", ", set)}]");
            }

            foreach (var (min, max) in range.Hulls)
            {
                for (long gx = (long)Math.Floor(min.X / 24); gx <= (long)Math.Floor(max.X / 24); gx++)
                {
                    for (long gy = (long)Math.Floor(min.Y / 24); gy <= (long)Math.Floor(max.Y / 24); gy++)
                    {
                        double w = Math.Min(max.X, 24.0 * (gx + 1)) - Math.Max(min.X, 24.0 * gx);
                        double h = Math.Min(max.Y, 24.0 * (gy + 1)) - Math.Max(min.Y, 24.0 * gy);
                        if (Oracle.OnMap(gx, gy) && w > Tolerance && h > Tolerance && !set.Contains(Oracle.CellOf((int)gx, (int)gy)))
                        {
                            return Outcome.Violated($"{Oracle.CellOf((int)gx, (int)gy)} is overlapped ({w:F4} × {h:F4} m) by a part but missing from [{string.Join(", ", set)}]");
                        }
                    }
                }
            }

            return Outcome.Holds;
        });

    /// <summary>PARTS-SOUNDNESS.</summary>
    public static readonly Invariant<PartsCase> PartsSoundness = new(
        "PARTS-SOUNDNESS",
        "Every cell in the set is an on-map land cell inside the smallest cell rectangle holding the anchor's cell and every part's box (within 1 mm), and none appears twice.",
        "facts §3.4 (one add_cell_block over the folded range)",
        Op.OutsideCellsParts,
        PartsDomain.Instance,
        (impl, c) =>
        {
            if (Range(c) is not { } range)
            {
                return Outcome.Vacuous;
            }

            var cells = impl.OutsideCellsParts(c.Parts);
            if (cells.Distinct().Count() != cells.Count)
            {
                return Outcome.Violated($"duplicate ids in [{string.Join(", ", cells)}]");
            }

            double lox = Math.Min(24.0 * range.AnchorX, range.Hulls.Min(h => h.Min.X)) - Tolerance;
            double loy = Math.Min(24.0 * range.AnchorY, range.Hulls.Min(h => h.Min.Y)) - Tolerance;
            double hix = Math.Max(24.0 * (range.AnchorX + 1), range.Hulls.Max(h => h.Max.X)) + Tolerance;
            double hiy = Math.Max(24.0 * (range.AnchorY + 1), range.Hulls.Max(h => h.Max.Y)) + Tolerance;
            foreach (var id in cells)
            {
                if (!Oracle.IsLandCellOnMap(id))
                {
                    return Outcome.Violated($"{id} is not a land cell on the map");
                }

                var (gx, gy) = Oracle.LcoordOf(id);
                if (24.0 * (gx + 1) < lox || 24.0 * gx > hix || 24.0 * (gy + 1) < loy || 24.0 * gy > hiy)
                {
                    return Outcome.Violated($"{id} lies outside the range of the anchor's cell and the parts' boxes");
                }
            }

            return Outcome.Holds;
        });

    /// <summary>Gets every parts invariant.</summary>
    public static IReadOnlyList<Invariant<PartsCase>> All { get; } = [PartsCoverage, PartsSoundness];

    // World-frame hulls (double) and the anchor's land cell; null when the anchor does not resolve or a hull is not finite.
    private static PartsRange? Range(PartsCase c)
    {
        if (c.Parts.Count == 0)
        {
            return null;
        }

        var a = c.Parts[0];
        var column = Oracle.Column(a.Cell, Oracle.Snap(a.Frame.Origin.X), Oracle.Snap(a.Frame.Origin.Y));
        if (!column.Ok)
        {
            return null;
        }

        var hulls = new List<(Vector2D Min, Vector2D Max)>();
        foreach (var p in c.Parts)
        {
            double bx = 192.0 * p.Cell.BlockX, by = 192.0 * p.Cell.BlockY;
            if (p.Always2D)
            {
                hulls.Add((new Vector2D(bx + p.Frame.Origin.X - p.Radius, by + p.Frame.Origin.Y - p.Radius), new Vector2D(bx + p.Frame.Origin.X + p.Radius, by + p.Frame.Origin.Y + p.Radius)));
                continue;
            }

            double minX = double.PositiveInfinity, minY = double.PositiveInfinity, maxX = double.NegativeInfinity, maxY = double.NegativeInfinity;
            for (int k = 0; k < 8; k++)
            {
                var b = p.Bounds;
                var (x, y) = Rotate(p.Frame.Rotation, (k & 1) == 0 ? b.Min.X : b.Max.X, (k & 2) == 0 ? b.Min.Y : b.Max.Y, (k & 4) == 0 ? b.Min.Z : b.Max.Z);
                minX = Math.Min(minX, bx + p.Frame.Origin.X + x);
                maxX = Math.Max(maxX, bx + p.Frame.Origin.X + x);
                minY = Math.Min(minY, by + p.Frame.Origin.Y + y);
                maxY = Math.Max(maxY, by + p.Frame.Origin.Y + y);
            }

            if (!double.IsFinite(minX + maxX + minY + maxY))
            {
                return null;
            }

            hulls.Add((new Vector2D(minX, minY), new Vector2D(maxX, maxY)));
        }

        return new PartsRange(column.X, column.Y, hulls);
    }

    // v' = v + 2w(q × v) + 2 q × (q × v), in double.
    private static (double X, double Y) Rotate(Quaternion q, double vx, double vy, double vz)
    {
        double qx = q.X, qy = q.Y, qz = q.Z, qw = q.W;
        double tx = 2 * ((qy * vz) - (qz * vy)), ty = 2 * ((qz * vx) - (qx * vz)), tz = 2 * ((qx * vy) - (qy * vx));
        return (vx + (qw * tx) + ((qy * tz) - (qz * ty)), vy + (qw * ty) + ((qz * tx) - (qx * tz)));
    }

    private readonly record struct Vector2D(double X, double Y);

    private sealed record PartsRange(int AnchorX, int AnchorY, IReadOnlyList<(Vector2D Min, Vector2D Max)> Hulls);
}
