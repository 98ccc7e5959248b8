using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Dat;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// Exact conformance: the implementation answers every query as the retail-faithful reference core does, in the mode
/// it declares (pick policy, documented deviations), except at numerical ties (<see cref="Conformance"/>).
/// These catch any deviation; the other invariants say what is wrong and catch a wrong reference.
/// </summary>
internal static class ConformanceInvariants
{
    /// <summary>FIND-CELL-CONFORMANCE.</summary>
    public static readonly Invariant<AnyWalk> FindCell = new(
        "FIND-CELL-CONFORMANCE",
        "For every query of every generated walk (open land, and scenes in each kind the implementation offers: static placement, movement transition, or both), the candidate list in insertion order with each entry's load-hint flag, the containing cell and HitsInteriorCell equal the reference core's answer to the same query in the implementation's declared mode (numerical ties excused: see docs/invariants.md).",
        "facts §3, §4, §5 (the reference core); docs/protocol.md (declared modes)",
        Op.FindCell,
        AnyWalkDomain.Instance,
        (impl, w) => w.Outdoor is { } walk ? OutdoorWalk(impl, walk) : SceneWalk(impl, w.Indoor!));

    /// <summary>OUTSIDE-CELLS-CONFORMANCE.</summary>
    public static readonly Invariant<OutdoorCase> OutsideCells = new(
        "OUTSIDE-CELLS-CONFORMANCE",
        "outside_cells answers every generated query with exactly the reference core's cells in the reference's insertion order (an answer of the exact double arithmetic, or a rounding-decided tie within 8 ulps, excused).",
        "facts §3.1–§3.3, §3.5",
        Op.OutsideCells,
        OutdoorDomain.Instance,
        (impl, q) =>
        {
            var reference = Conformance.ReferenceFor(impl);
            var got = impl.OutsideCells(q.Cell, q.Origin, q.Spheres);
            if (Conformance.HasNonFiniteCentre(q.Spheres))
            {
                return Outcome.Vacuous; // asked (a throw is a violation), not judged: NONFINITE-SPHERE-ENDS-LOOP, a hardening rule, does (facts §6.17)
            }

            var want = reference.OutsideCells(q.Cell, q.Origin, q.Spheres);
            if (got.SequenceEqual(want)
                || Conformance.ExcusedOnOpenLand(got, want, Conformance.AlternateFor(impl).OutsideCells(q.Cell, q.Origin, q.Spheres), p => reference.OutsideCells(q.Cell, q.Origin, p), (a, b) => a.SequenceEqual(b), q.Spheres))
            {
                return Outcome.Holds;
            }

            int k = got.Zip(want).TakeWhile(x => x.First == x.Second).Count();
            return Outcome.Violated($"cells differ at position {k}: got [{string.Join(", ", got)}], reference [{string.Join(", ", want)}]");
        });

    /// <summary>FIND-CELL-QUERY-CONFORMANCE: one open-land find_cell query from any kind of position, answered exactly as the reference.</summary>
    public static readonly Invariant<OutdoorCase> FindCellQuery = new(
        "FIND-CELL-QUERY-CONFORMANCE",
        "find_cell answers every generated open-land query (from a land, env, block-id, id-0 or malformed position, with or without spheres; with no current cell and with each of its first three candidates as the current cell) with exactly the reference core's candidates in insertion order and containing cell: strict neighbour tests and the last-wins pick on exact lines are pinned (an answer of the exact double arithmetic, or a rounding-decided tie within 8 ulps, excused).",
        "facts §3.2, §3.3, §4 steps 2–4, §6.5, §6.7, §6.12",
        Op.FindCell,
        OutdoorDomain.Instance,
        FindCellQueryCheck);

    /// <summary>LANDDEFS-CONFORMANCE.</summary>
    public static readonly Invariant<LandCase> LandDefs = new(
        "LANDDEFS-CONFORMANCE",
        "Every LandDefs operation the implementation offers answers every generated input as the reference core does: the same success flag, lcoord, id and re-based point (the point within 2 ulps; numerical ties within 8 ulps of x or y excused).",
        "facts §1, §2",
        Op.GetOutsideLcoord | Op.AdjustToOutside,
        LandDomain.Instance,
        LandDefsCheck);

    /// <summary>Gets every conformance invariant.</summary>
    public static IReadOnlyList<Invariant> All { get; } = [LandDefs, OutsideCells, FindCellQuery, FindCell];

    /// <summary>
    /// Gets every conformance invariant of the catalogue: <see cref="All"/> and PARTS-INDOOR-CONFORMANCE, which is listed
    /// with the parts invariants indoors (<see cref="PartsIndoorInvariants.All"/>) so that the catalogue's order stays as it was.
    /// </summary>
    public static IReadOnlyList<Invariant> Every { get; } = [.. All, PartsIndoorInvariants.Conformance];

    private static Outcome FindCellQueryCheck(ICellPhysics impl, OutdoorCase q)
    {
        var first = impl.FindCell(q.Cell, q.Origin, q.Spheres, CellId.None);
        if (Conformance.HasNonFiniteCentre(q.Spheres))
        {
            return Outcome.Vacuous; // asked, not judged (facts §6.17: what retail does is a hardening question)
        }

        var reference = Conformance.ReferenceFor(impl);
        var alternate = Conformance.AlternateFor(impl);
        foreach (var current in first.Cells.Take(3).Prepend(CellId.None))
        {
            var got = current.IsNone ? first : impl.FindCell(q.Cell, q.Origin, q.Spheres, current);
            var want = reference.FindCell(q.Cell, q.Origin, q.Spheres, current);
            if (Conformance.Difference(got, want) is string why
                && !Conformance.ExcusedOnOpenLand(got, want, alternate.FindCell(q.Cell, q.Origin, q.Spheres, current), p => reference.FindCell(q.Cell, q.Origin, p, current), (a, b) => Conformance.Difference(a, b) is null, q.Spheres))
            {
                return Outcome.Violated($"find_cell from {q.Cell}{(q.Spheres.Count == 0 ? $" (no spheres, origin {OutdoorCase.Format(new Sphere(q.Origin, 0))})" : string.Empty)}, current {(current.IsNone ? "none" : current.ToString())}: {why}");
            }
        }

        return Outcome.Holds;
    }

    private static Outcome OutdoorWalk(ICellPhysics impl, Walk walk)
    {
        var reference = Conformance.ReferenceFor(impl);
        var session = Conformance.WalkReferenceFor(impl); // asked every query of the walk once, in order (stale cells declared: one array)
        var alternate = Conformance.AlternateFor(impl);
        var trace = WalkRunner.Run(impl, walk);
        for (int i = 0; i < trace.Count; i++)
        {
            var s = trace[i];
            var current = i == 0 ? CellId.None : trace[i - 1].Current;
            var got = s.Answer!;
            var want = session.FindCell(s.Query.Cell, s.Query.Origin, s.Query.Spheres, current);
            if (Conformance.Difference(got, want) is string why
                && !Conformance.ExcusedOnOpenLand(got, want, alternate.FindCell(s.Query.Cell, s.Query.Origin, s.Query.Spheres, current), p => reference.FindCell(s.Query.Cell, s.Query.Origin, p, current), (a, b) => Conformance.Difference(a, b) is null, s.Query.Spheres))
            {
                return Outcome.ViolatedAt(s.Index, $"step {s.Index} (find_cell from {s.Query.Cell}, spheres [{string.Join("; ", s.Query.Spheres.Select(OutdoorCase.Format))}], current {current}): {why}");
            }
        }

        return Outcome.Holds;
    }

    private static Outcome SceneWalk(ICellPhysics impl, SceneWalk w)
    {
        if (!SceneQueryKinds.OffersScenes(impl.Ops))
        {
            return Outcome.VacuousBecause("the implementation offers neither find_cell_scene nor find_cell_transition");
        }

        var scene = Transports.ScenesAsRecords(impl) ? DatRoundTrip.Of(w.Scene) : w.Scene; // what the implementation was sent
        foreach (bool loadCells in SceneQueryKinds.Offered(impl.Ops))
        {
            var trace = SceneWalkRunner.Run(impl, w, loadCells);
            // Asked every query the implementation was asked in this walk, once and in order: with ace-keeps-stale-cells
            // declared its array then holds what the implementation's holds (facts §7 #6), so the comparison stays exact.
            var reference = Conformance.WalkReferenceFor(impl);
            for (int i = 0; i < trace.Count; i++)
            {
                var s = trace[i];
                var current = i == 0 ? CellId.None : trace[i - 1].Current;
                var got = s.Answer!;
                var want = reference.FindCell(scene, s.Query.Cell, s.Query.Spheres, current, loadCells);
                int at = i;
                if (Conformance.Difference(got, want) is string why
                    && Conformance.Probes(s.Query.Spheres).All(p => Conformance.Difference(got, ProbeAnswer(impl, trace, at, scene, p, loadCells)) is not null))
                {
                    string kind = loadCells ? "transition" : "static";
                    return Outcome.ViolatedAt(s.Index, $"step {s.Index} ({kind} find_cell from {s.Query.Cell}, spheres [{string.Join("; ", s.Query.Spheres.Select(OutdoorCase.Format))}], current {current}): {why}");
                }
            }
        }

        return Outcome.Holds;
    }

    // The declared reference's answer to step i of a scene walk with its spheres moved to a probe: under stale cells the
    // earlier queries are asked first of a fresh walk session (only when the answers differ, so a conforming walk pays nothing).
    private static FindCellResult ProbeAnswer(ICellPhysics impl, IReadOnlyList<WalkStep> trace, int i, AcPhys.Contract.Scene scene, Sphere[] probe, bool loadCells)
    {
        var reference = Conformance.WalkReferenceFor(impl);
        for (int j = 0; j < i && impl.Indoor.AceKeepsStaleCells; j++)
        {
            reference.FindCell(scene, trace[j].Query.Cell, trace[j].Query.Spheres, j == 0 ? CellId.None : trace[j - 1].Current, loadCells);
        }

        return reference.FindCell(scene, trace[i].Query.Cell, probe, i == 0 ? CellId.None : trace[i - 1].Current, loadCells);
    }

    private static Outcome LandDefsCheck(ICellPhysics impl, LandCase c)
    {
        var reference = Conformance.ReferenceFor(impl);
        var ops = impl.Ops;
        if ((ops & Op.BlockIdToLcoord) != 0 && Lcoords(impl.BlockIdToLcoord(c.Cell, out var a), a, reference.BlockIdToLcoord(c.Cell, out var b), b) is string m1)
        {
            return Outcome.Violated($"blockid_to_lcoord({c.Cell}): {m1}");
        }

        if ((ops & Op.GidToLcoord) != 0 && Lcoords(impl.GidToLcoord(c.Cell, out a), a, reference.GidToLcoord(c.Cell, out b), b) is string m2)
        {
            return Outcome.Violated($"gid_to_lcoord({c.Cell}): {m2}");
        }

        if ((ops & Op.LcoordToGid) != 0 && impl.LcoordToGid(c.Lcoord.X, c.Lcoord.Y) is var g && reference.LcoordToGid(c.Lcoord.X, c.Lcoord.Y) is var wantGid && g != wantGid)
        {
            return Outcome.Violated($"lcoord_to_gid{c.Lcoord}: got {g}, reference {wantGid}");
        }

        if ((ops & Op.InboundValidCellId) != 0 && impl.InboundValidCellId(c.Cell) is var valid && reference.InboundValidCellId(c.Cell) is var wantValid && valid != wantValid)
        {
            return Outcome.Violated($"inbound_valid_cellid({c.Cell}): got {valid}, reference {wantValid}");
        }

        var probes = LandProbes(c).ToArray();
        bool gotOk = impl.GetOutsideLcoord(c.Cell, c.X, c.Y, out var lc);
        if (!float.IsFinite(c.X) || !float.IsFinite(c.Y))
        {
            impl.AdjustToOutside(c.Cell, c.X, c.Y);
            return Outcome.Holds; // asked, not judged: retail's answer is a hardening question (facts §6.17, NONFINITE-REJECTED)
        }

        if (Lcoords(gotOk, lc, reference.GetOutsideLcoord(c.Cell, c.X, c.Y, out var want), want) is string m3
            && probes.All(p => Lcoords(gotOk, lc, reference.GetOutsideLcoord(c.Cell, p.X, p.Y, out var pw), pw) is not null))
        {
            return Outcome.Violated($"get_outside_lcoord({c}): {m3}");
        }

        var adjusted = impl.AdjustToOutside(c.Cell, c.X, c.Y);
        var expected = reference.AdjustToOutside(c.Cell, c.X, c.Y);
        if (adjusted.Ok != expected.Ok || adjusted.Cell != expected.Cell)
        {
            if (probes.Any(p => reference.AdjustToOutside(c.Cell, p.X, p.Y) is var e && e.Ok == adjusted.Ok && e.Cell == adjusted.Cell))
            {
                return Outcome.Holds; // a numerical tie (see Conformance)
            }

            return Outcome.Violated($"adjust_to_outside({c}): got ok={adjusted.Ok} {adjusted.Cell}, reference ok={expected.Ok} {expected.Cell}");
        }

        if (expected.Ok && (!Near(adjusted.X, expected.X) || !Near(adjusted.Y, expected.Y)))
        {
            return Outcome.Violated($"adjust_to_outside({c}): re-based point ({FloatText.Format(adjusted.X)}, {FloatText.Format(adjusted.Y)}), reference ({FloatText.Format(expected.X)}, {FloatText.Format(expected.Y)})");
        }

        return Outcome.Holds;
    }

    // Lcoords agree when both fail, or both succeed with the same lcoord (a failed call's lcoord means nothing).
    private static string? Lcoords(bool gotOk, Lcoord got, bool wantOk, Lcoord want) =>
        gotOk != wantOk ? $"got ok={gotOk}{(gotOk ? " " + got : string.Empty)}, reference ok={wantOk}{(wantOk ? " " + want : string.Empty)}"
        : gotOk && got != want ? $"got {got}, reference {want}"
        : null;

    private static IEnumerable<(float X, float Y)> LandProbes(LandCase c)
    {
        if (!float.IsFinite(c.X) || !float.IsFinite(c.Y))
        {
            yield break; // a non-finite coordinate has no neighbourhood
        }

        float step = Conformance.TieStep([c.X, c.Y]);
        foreach (var (dx, dy) in new[] { (1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1) })
        {
            yield return (c.X + (dx * step), c.Y + (dy * step));
        }
    }

    private static bool Near(float a, float b) =>
        a.Equals(b) || (float.IsFinite(a) && float.IsFinite(b) && MathF.Abs(a - b) <= 2 * (MathF.BitIncrement(MathF.Max(MathF.Abs(a), MathF.Abs(b))) - MathF.Max(MathF.Abs(a), MathF.Abs(b))));
}
