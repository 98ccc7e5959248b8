using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>The LandDefs invariants (facts §1–§2): lcoords, cell ids, the outside column and AdjustToOutside.</summary>
public static class LandInvariants
{
    /// <summary>Tolerance for a world position kept across a re-seat: the EPS snap plus one rounding of a value below 192 m.</summary>
    public const double PositionTolerance = 0.0002 + 1e-5;

    /// <summary>LCOORD-ROUNDTRIP.</summary>
    public static readonly Invariant<LandCase> LcoordRoundTrip = new(
        "LCOORD-ROUNDTRIP",
        "lcoord_to_gid and gid_to_lcoord are inverse on the whole map: every on-map lcoord maps to its land cell and back, and every on-map land cell id maps to its lcoord and back.",
        "facts §1.2, §1.3, §2",
        Op.LcoordToGid | Op.GidToLcoord,
        LandDomain.Instance,
        (impl, c) =>
        {
            bool applied = false;
            if (Oracle.OnMap(c.Lcoord.X, c.Lcoord.Y))
            {
                applied = true;
                var expected = Oracle.CellOf(c.Lcoord.X, c.Lcoord.Y);
                var id = impl.LcoordToGid(c.Lcoord.X, c.Lcoord.Y);
                if (id != expected)
                {
                    return Outcome.Violated($"lcoord_to_gid{c.Lcoord} = {id}, expected {expected}");
                }

                if (!impl.GidToLcoord(id, out var back) || back != c.Lcoord)
                {
                    return Outcome.Violated($"gid_to_lcoord({id}) = {Show(impl.GidToLcoord(id, out back), back)}, expected {c.Lcoord}");
                }
            }

            if (Oracle.IsLandCellOnMap(c.Cell))
            {
                applied = true;
                var (ex, ey) = Oracle.LcoordOf(c.Cell);
                if (!impl.GidToLcoord(c.Cell, out var lc) || lc != new Lcoord(ex, ey))
                {
                    return Outcome.Violated($"gid_to_lcoord({c.Cell}) = {Show(impl.GidToLcoord(c.Cell, out lc), lc)}, expected ({ex}, {ey})");
                }

                var again = impl.LcoordToGid(lc.X, lc.Y);
                if (again != c.Cell)
                {
                    return Outcome.Violated($"lcoord_to_gid{lc} = {again}, expected {c.Cell}");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        });

    /// <summary>LCOORD-BLOCK.</summary>
    public static readonly Invariant<LandCase> LcoordBlock = new(
        "LCOORD-BLOCK",
        "blockid_to_lcoord(id) is (8·bx, 8·by) for every non-zero id on the map whatever its low word, and equals the block part of gid_to_lcoord(id) for land cells.",
        "facts §1.3, §2",
        Op.BlockIdToLcoord | Op.GidToLcoord,
        LandDomain.Instance,
        (impl, c) =>
        {
            if (c.Cell.IsNone || !Oracle.BlockOnMap(c.Cell))
            {
                return Outcome.Vacuous;
            }

            var expected = new Lcoord(c.Cell.BlockX * 8, c.Cell.BlockY * 8);
            if (!impl.BlockIdToLcoord(c.Cell, out var block) || block != expected)
            {
                return Outcome.Violated($"blockid_to_lcoord({c.Cell}) = {Show(impl.BlockIdToLcoord(c.Cell, out block), block)}, expected {expected}");
            }

            if (Oracle.IsLandCellOnMap(c.Cell))
            {
                if (!impl.GidToLcoord(c.Cell, out var lc))
                {
                    return Outcome.Violated($"gid_to_lcoord({c.Cell}) failed for a land cell on the map");
                }

                var blockPart = new Lcoord(lc.X - (lc.X % 8), lc.Y - (lc.Y % 8));
                if (blockPart != block)
                {
                    return Outcome.Violated($"block part of gid_to_lcoord({c.Cell}) = {lc} is {blockPart}, blockid_to_lcoord = {block}");
                }
            }

            return Outcome.Holds;
        });

    /// <summary>OUTSIDE-LCOORD-GEOMETRY.</summary>
    public static readonly Invariant<LandCase> OutsideLcoordGeometry = new(
        "OUTSIDE-LCOORD-GEOMETRY",
        "get_outside_lcoord(id, x, y) is the 24 m column containing a finite point, (8·bx + ⌊x/24⌋, 8·by + ⌊y/24⌋) with floor toward −∞, and fails exactly when the id is malformed or the column is off the map (non-finite points: NONFINITE-REJECTED, a hardening rule, facts §6.17).",
        "facts §2 get_outside_lcoord, §6.2",
        Op.GetOutsideLcoord,
        LandDomain.Instance,
        FiniteOnly((impl, c) =>
        {
            var expected = Oracle.Column(c.Cell, c.X, c.Y);
            bool ok = impl.GetOutsideLcoord(c.Cell, c.X, c.Y, out var lc);
            if (ok != expected.Ok || (ok && (lc.X != expected.X || lc.Y != expected.Y)))
            {
                return Outcome.Violated($"get_outside_lcoord = {Show(ok, lc)}, expected {Show(expected.Ok, new Lcoord(expected.X, expected.Y))}");
            }

            return Outcome.Holds;
        }));

    /// <summary>ADJUST-GEOMETRY.</summary>
    public static readonly Invariant<LandCase> AdjustGeometry = new(
        "ADJUST-GEOMETRY",
        "AdjustToOutside re-seats to the land cell whose 24 m column contains the point after the ±EPS snap, and fails (id 0) exactly when the low word is invalid or that column is off the map.",
        "facts §2.1, §6.3, §6.4",
        Op.AdjustToOutside,
        LandDomain.Instance,
        FiniteOnly((impl, c) =>
        {
            var r = impl.AdjustToOutside(c.Cell, c.X, c.Y);
            if (!Oracle.LowInRange(c.Cell.Low))
            {
                return r.Ok || !r.Cell.IsNone
                    ? Outcome.Violated($"adjust_to_outside = {Show(r)}, expected failure with id 0 (low word {c.Cell.Low:X4} invalid)")
                    : Outcome.Holds;
            }

            float sx = Oracle.Snap(c.X), sy = Oracle.Snap(c.Y);
            var column = Oracle.Column(c.Cell, sx, sy);
            if (!column.Ok)
            {
                return r.Ok || !r.Cell.IsNone
                    ? Outcome.Violated($"adjust_to_outside = {Show(r)}, expected failure with id 0 (column off the map)")
                    : Outcome.Holds;
            }

            var expected = Oracle.CellOf(column.X, column.Y);
            return r.Ok && r.Cell == expected
                ? Outcome.Holds
                : Outcome.Violated($"adjust_to_outside = {Show(r)}, expected {expected} (snapped point {FloatText.Format(sx)}, {FloatText.Format(sy)})");
        }));

    /// <summary>ADJUST-IDEMPOTENT.</summary>
    public static readonly Invariant<LandCase> AdjustIdempotent = new(
        "ADJUST-IDEMPOTENT",
        "Re-seating a re-seated point keeps its position (but for an EPS-band snap to 0) and its cell, unless the float32 re-base rounded the point exactly onto the cell's east or north line, where it moves once to the neighbour across that line; a third re-seat changes nothing.",
        "facts §2.1, §6.5 (tie band: docs/numerics.md)",
        Op.AdjustToOutside,
        LandDomain.Instance,
        FiniteOnly((impl, c) =>
        {
            var r1 = impl.AdjustToOutside(c.Cell, c.X, c.Y);
            if (!r1.Ok)
            {
                return Outcome.Vacuous;
            }

            float sx = Oracle.Snap(r1.X), sy = Oracle.Snap(r1.Y);
            var column = Oracle.Column(r1.Cell, sx, sy);
            if (!column.Ok)
            {
                return Outcome.Violated($"re-seated point {Show(r1)} is not in a column on the map");
            }

            var expectedCell = Oracle.CellOf(column.X, column.Y);
            if (expectedCell != r1.Cell && !OnUpperLineOf(r1.Cell, sx, sy))
            {
                return Outcome.Violated($"re-seated point {Show(r1)} lies in {expectedCell}, not on a line of {r1.Cell}");
            }

            var r2 = impl.AdjustToOutside(r1.Cell, r1.X, r1.Y);
            var expected2 = new AdjustResult(true, expectedCell, sx, sy);
            if (!SameBits(r2, expected2))
            {
                return Outcome.Violated($"second re-seat of {Show(r1)} gave {Show(r2)}, expected {Show(expected2)}");
            }

            var r3 = impl.AdjustToOutside(r2.Cell, r2.X, r2.Y);
            return SameBits(r3, r2)
                ? Outcome.Holds
                : Outcome.Violated($"third re-seat of {Show(r2)} gave {Show(r3)}");
        }));

    /// <summary>ADJUST-PRESERVES-POSITION.</summary>
    public static readonly Invariant<LandCase> AdjustPreservesPosition = new(
        "ADJUST-PRESERVES-POSITION",
        "The world point is the same before and after a successful re-seat, within the EPS snap plus one float32 rounding (2.1e-4 m).",
        "facts §2.1 step 4",
        Op.AdjustToOutside,
        LandDomain.Instance,
        FiniteOnly((impl, c) =>
        {
            var r = impl.AdjustToOutside(c.Cell, c.X, c.Y);
            if (!r.Ok)
            {
                return Outcome.Vacuous;
            }

            double bx = 192.0 * c.Cell.BlockX, by = 192.0 * c.Cell.BlockY;
            double ax = 192.0 * r.Cell.BlockX, ay = 192.0 * r.Cell.BlockY;
            double dx = (ax + r.X) - (bx + c.X), dy = (ay + r.Y) - (by + c.Y);
            return Math.Abs(dx) <= PositionTolerance && Math.Abs(dy) <= PositionTolerance
                ? Outcome.Holds
                : Outcome.Violated($"world point moved by ({dx:R}, {dy:R}) m: {Show(r)}");
        }));

    /// <summary>ADJUST-RANGE.</summary>
    public static readonly Invariant<LandCase> AdjustRange = new(
        "ADJUST-RANGE",
        "A successful re-seat yields a land cell on the map and a re-based point with x, y in [0, 192) that lies in that cell's closed 24 m square (on its east or north line only where float32 rounding of the re-base put it there).",
        "facts §2.1 consequences, §5.5 (closed squares)",
        Op.AdjustToOutside,
        LandDomain.Instance,
        FiniteOnly((impl, c) =>
        {
            var r = impl.AdjustToOutside(c.Cell, c.X, c.Y);
            if (!r.Ok)
            {
                return Outcome.Vacuous;
            }

            if (!Oracle.IsLandCellOnMap(r.Cell))
            {
                return Outcome.Violated($"re-seated id {r.Cell} is not a land cell on the map");
            }

            if (!(r.X >= 0 && r.X < 192 && r.Y >= 0 && r.Y < 192))
            {
                return Outcome.Violated($"re-based point ({FloatText.Format(r.X)}, {FloatText.Format(r.Y)}) outside [0, 192)");
            }

            int idx = r.Cell.Low - 1;
            double west = 24.0 * (idx / 8), south = 24.0 * (idx % 8);
            return r.X >= west && r.X <= west + 24 && r.Y >= south && r.Y <= south + 24
                ? Outcome.Holds
                : Outcome.Violated($"re-based point ({FloatText.Format(r.X)}, {FloatText.Format(r.Y)}) is not in the closed square of {r.Cell}");
        }));

    /// <summary>MAP-EDGE.</summary>
    public static readonly Invariant<LandCase> MapEdge = new(
        "MAP-EDGE",
        "Lcoords 0 and 2039 are valid on both axes while −1 and 2040 (and anything beyond) are not, and an id with block byte 0xFF is rejected by every LandDefs function, all without an exception.",
        "facts §1.3, §6.3",
        Op.LandDefs,
        LandDomain.Instance,
        (impl, c) =>
        {
            bool applied = false;
            var cls = BoundaryClasses.OfLcoord(c.Lcoord);
            if (cls == "lcoord:off-map")
            {
                applied = true;
                var id = impl.LcoordToGid(c.Lcoord.X, c.Lcoord.Y);
                if (!id.IsNone)
                {
                    return Outcome.Violated($"lcoord_to_gid{c.Lcoord} = {id} for an lcoord off the map, expected 0x00000000");
                }
            }
            else if (cls == "lcoord:edge")
            {
                applied = true;
                var id = impl.LcoordToGid(c.Lcoord.X, c.Lcoord.Y);
                if (id.IsNone || !Oracle.IsLandCellOnMap(id))
                {
                    return Outcome.Violated($"lcoord_to_gid{c.Lcoord} = {id} for an edge lcoord, expected a land cell on the map");
                }
            }

            if (c.Cell.BlockX == 0xFF || c.Cell.BlockY == 0xFF)
            {
                applied = true;
                if (impl.BlockIdToLcoord(c.Cell, out var b))
                {
                    return Outcome.Violated($"blockid_to_lcoord({c.Cell}) accepted a 0xFF block byte: {b}");
                }

                if (impl.InboundValidCellId(c.Cell))
                {
                    return Outcome.Violated($"inbound_valid_cellid({c.Cell}) accepted a 0xFF block byte");
                }

                if (impl.GidToLcoord(c.Cell, out var g))
                {
                    return Outcome.Violated($"gid_to_lcoord({c.Cell}) accepted a 0xFF block byte: {g}");
                }

                if (impl.GetOutsideLcoord(c.Cell, c.X, c.Y, out var o))
                {
                    return Outcome.Violated($"get_outside_lcoord({c.Cell}, …) accepted a 0xFF block byte: {o}");
                }

                var r = impl.AdjustToOutside(c.Cell, c.X, c.Y);
                if (r.Ok || !r.Cell.IsNone)
                {
                    return Outcome.Violated($"adjust_to_outside({c.Cell}, …) accepted a 0xFF block byte: {Show(r)}");
                }
            }

            return applied ? Outcome.Holds : Outcome.Vacuous;
        });

    // Retail has no finiteness test and most likely re-seats a non-finite coordinate in its block's own column (facts
    // §6.17), so the geometry invariants state retail only for finite points: a non-finite point is still asked (an
    // exception is a violation) but judged only by NONFINITE-REJECTED, a hardening rule.
    private static Func<ICellPhysics, LandCase, Outcome> FiniteOnly(Func<ICellPhysics, LandCase, Outcome> check) => (impl, c) =>
    {
        if (float.IsFinite(c.X) && float.IsFinite(c.Y))
        {
            return check(impl, c);
        }

        if ((impl.Ops & Op.GetOutsideLcoord) != 0)
        {
            impl.GetOutsideLcoord(c.Cell, c.X, c.Y, out _);
        }

        if ((impl.Ops & Op.AdjustToOutside) != 0)
        {
            impl.AdjustToOutside(c.Cell, c.X, c.Y);
        }

        return Outcome.Vacuous;
    };

    /// <summary>NONFINITE-REJECTED.</summary>
    public static readonly Invariant<LandCase> NonFiniteRejected = new(
        "NONFINITE-REJECTED",
        "A NaN or infinite coordinate never yields a cell: get_outside_lcoord and AdjustToOutside fail (id 0) without an exception, and in particular NaN never becomes lcoord 0.",
        "facts §2, §6.15; issue #2 (.NET 9 (int)NaN == 0)",
        Op.GetOutsideLcoord | Op.AdjustToOutside,
        LandDomain.Instance,
        (impl, c) =>
        {
            if (float.IsFinite(c.X) && float.IsFinite(c.Y))
            {
                return Outcome.Vacuous;
            }

            if (impl.GetOutsideLcoord(c.Cell, c.X, c.Y, out var lc))
            {
                return Outcome.Violated($"get_outside_lcoord accepted a non-finite point: {lc}");
            }

            var r = impl.AdjustToOutside(c.Cell, c.X, c.Y);
            return r.Ok || !r.Cell.IsNone
                ? Outcome.Violated($"adjust_to_outside accepted a non-finite point: {Show(r)}")
                : Outcome.Holds;
        });

    /// <summary>Gets every LandDefs invariant, in catalogue order.</summary>
    public static IReadOnlyList<Invariant<LandCase>> All { get; } =
    [
        LcoordRoundTrip, LcoordBlock, OutsideLcoordGeometry, AdjustGeometry, AdjustIdempotent, AdjustPreservesPosition,
        AdjustRange, MapEdge, NonFiniteRejected,
    ];

    private static string Show(bool ok, Lcoord lc) => ok ? lc.ToString() : "failure";

    private static string Show(AdjustResult r) =>
        $"{(r.Ok ? "ok" : "failed")} {r.Cell} ({FloatText.Format(r.X)}, {FloatText.Format(r.Y)})";

    // The float32 tie band (docs/numerics.md): a negative coordinate re-based by v + 192·k can round to exactly
    // 24·(c + 1), the east/north line of the cell floor() chose before rounding.
    private static bool OnUpperLineOf(CellId cell, float x, float y)
    {
        int idx = cell.Low - 1;
        return x == 24f * ((idx / 8) + 1) || y == 24f * ((idx % 8) + 1);
    }

    private static bool SameBits(AdjustResult a, AdjustResult b) =>
        a.Ok == b.Ok && a.Cell == b.Cell
        && BitConverter.SingleToInt32Bits(a.X) == BitConverter.SingleToInt32Bits(b.X)
        && BitConverter.SingleToInt32Bits(a.Y) == BitConverter.SingleToInt32Bits(b.Y);
}
