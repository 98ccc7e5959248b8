using System.Collections.Concurrent;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Core.Text;

namespace AcPhys.Spec.Invariants;

/// <summary>
/// What the conformance invariants share: the reference core in the mode an implementation declares (its pick and its
/// documented deviations, never failed for those), the comparison of two answers that names the first position where
/// they differ, and the numerical-tie probes.
/// </summary>
/// <remarks>
/// The reference computes in float32 as retail does. A port whose arithmetic rounds in another order (a matrix for the
/// quaternion, <c>x · (1/24)</c> for <c>x / 24</c>) can land on the other side of a boundary when the query is within a
/// few ulps of it. Such a query is a numerical tie, not a rule. On open land the reference also computes in exact double
/// arithmetic: a difference is excused when the implementation answers as the exact arithmetic does, or when the two
/// arithmetics disagree (rounding decides) and the implementation's answer equals the reference's answer to the query
/// moved by at most <see cref="TieUlps"/> ulps (<see cref="Probes"/>). Exact ties that retail decides by rule (a disc that
/// exactly touches a line, the last-wins pick on a line) are exact in both arithmetics, so they are pinned. In scenes
/// (float32 only) every difference that a probe's answer explains is excused, exact ties included.
/// </remarks>
public static class Conformance
{
    /// <summary>How many float32 ulps of the largest coordinate a probe moves a query.</summary>
    public const int TieUlps = 8;

    private static readonly ConcurrentDictionary<(PickPolicy, IndoorFidelity, OutdoorFidelity), ReferenceAdapter> References = new();

    /// <summary>Returns the reference core in the mode the implementation declares.</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The reference. One query asked of it starts from an empty array, ACE's stale cells declared or not (their
    /// array lives for one walk: <see cref="WalkReferenceFor"/>).</returns>
    public static ReferenceAdapter ReferenceFor(ICellPhysics impl)
    {
        return Reference(impl, impl.Outdoor);
    }

    /// <summary>
    /// Returns the reference that answers one walk's queries when they are asked of it in the order the implementation was
    /// asked them: with ace-keeps-stale-cells declared, a walk session of the declared reference (one array for the walk,
    /// never cleared: facts §7 #6), so the comparison stays exact; otherwise the declared reference itself.
    /// </summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>A reference for one walk; ask it every query of the walk once, in order.</returns>
    public static ReferenceAdapter WalkReferenceFor(ICellPhysics impl) =>
        impl.Indoor.AceKeepsStaleCells ? ReferenceFor(impl).WalkSession() : ReferenceFor(impl);

    /// <summary>
    /// Returns the reference in the declared mode but the other outdoor arithmetic (double for a float32 implementation,
    /// float32 for one that declares double). On open land a query whose two answers differ is decided by rounding, not
    /// by a rule; elsewhere the two agree, exact ties included (they are exact in both).
    /// </summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The reference in the other arithmetic.</returns>
    public static ReferenceAdapter AlternateFor(ICellPhysics impl)
    {
        var other = impl.Outdoor with { Precision = impl.Outdoor.Precision == OutdoorPrecision.Double ? OutdoorPrecision.Float32 : OutdoorPrecision.Double };
        return Reference(impl, other);
    }

    /// <summary>
    /// Decides an open-land difference: excused when the implementation's answer is the other arithmetic's, or when the
    /// query is decided by rounding (the two arithmetics disagree) and a probe's answer equals it.
    /// </summary>
    /// <typeparam name="T">The answer type.</typeparam>
    /// <param name="got">The implementation's answer.</param>
    /// <param name="want">The declared-mode reference's answer.</param>
    /// <param name="alternate">The other arithmetic's answer.</param>
    /// <param name="probe">The declared-mode reference's answer to a probe query (by probe index).</param>
    /// <param name="same">Equality of answers.</param>
    /// <param name="spheres">The query's spheres.</param>
    /// <returns>True when excused.</returns>
    public static bool ExcusedOnOpenLand<T>(T got, T want, T alternate, Func<Sphere[], T> probe, Func<T, T, bool> same, IReadOnlyList<Sphere> spheres) =>
        same(got, alternate) || (!same(want, alternate) && Probes(spheres).Any(p => same(got, probe(p))));

    /// <summary>Tests whether a sphere centre has a non-finite x or y: such queries are judged only by hardening rules (facts §6.17).</summary>
    /// <param name="spheres">The spheres.</param>
    /// <returns>True when some centre is NaN or infinite in x or y.</returns>
    public static bool HasNonFiniteCentre(IReadOnlyList<Sphere> spheres)
    {
        foreach (var s in spheres)
        {
            if (!float.IsFinite(s.Center.X) || !float.IsFinite(s.Center.Y))
            {
                return true;
            }
        }

        return false;
    }

    /// <summary>Returns the step of one ulp-probe: <see cref="TieUlps"/> ulps of the largest magnitude among the values (at least that of 1 m).</summary>
    /// <param name="values">Coordinates.</param>
    /// <returns>The step, metres.</returns>
    public static float TieStep(IEnumerable<float> values)
    {
        float big = 1f;
        foreach (float v in values)
        {
            if (float.IsFinite(v))
            {
                big = MathF.Max(big, MathF.Abs(v));
            }
        }

        return TieUlps * (MathF.BitIncrement(big) - big);
    }

    /// <summary>
    /// Returns the probe queries of a sphere list: every centre moved together by ±step along x, y, z and the four
    /// horizontal diagonals, and every radius by ±step.
    /// </summary>
    /// <param name="spheres">The spheres.</param>
    /// <returns>The probes.</returns>
    public static IEnumerable<Sphere[]> Probes(IReadOnlyList<Sphere> spheres)
    {
        float step = TieStep(spheres.SelectMany(s => new[] { s.Center.X, s.Center.Y, s.Center.Z, s.Radius }));
        var moves = new System.Numerics.Vector3[]
        {
            new(step, 0, 0), new(-step, 0, 0), new(0, step, 0), new(0, -step, 0), new(0, 0, step), new(0, 0, -step),
            new(step, step, 0), new(step, -step, 0), new(-step, step, 0), new(-step, -step, 0),
        };
        foreach (var m in moves)
        {
            yield return [.. spheres.Select(s => new Sphere(s.Center + m, s.Radius))];
        }

        yield return [.. spheres.Select(s => new Sphere(s.Center, s.Radius + step))];
        yield return [.. spheres.Select(s => new Sphere(s.Center, MathF.Max(0, s.Radius - step)))];
    }

    // The reference with the implementation's pick and indoor fidelity and an outdoor fidelity.
    private static ReferenceAdapter Reference(ICellPhysics impl, OutdoorFidelity outdoor) =>
        References.GetOrAdd((impl.Pick, impl.Indoor, outdoor), k => new ReferenceAdapter(k.Item1, outdoor: k.Item3) { Indoor = k.Item2 });

    /// <summary>
    /// Compares a find_cell answer with the reference's: the candidates in insertion order with their load-hint flags,
    /// the containing cell and HitsInteriorCell (a flag the implementation did not report is not compared).
    /// </summary>
    /// <param name="got">The implementation's answer.</param>
    /// <param name="want">The reference's answer.</param>
    /// <returns>Null when they agree, else what differs, with both lists.</returns>
    public static string? Difference(FindCellResult got, FindCellResult want)
    {
        string Lists() => $"got [{Show(got)}] → {Cell(got.Containing)}, reference [{Show(want)}] → {Cell(want.Containing)}";
        int n = Math.Min(got.Cells.Count, want.Cells.Count);
        for (int i = 0; i < n; i++)
        {
            if (got.Cells[i] != want.Cells[i])
            {
                return $"candidates differ at position {i}: {Lists()}";
            }

            if (got.Loaded is { } gl && want.Loaded is { } wl && gl[i] != wl[i])
            {
                return $"candidate {i} ({got.Cells[i]}) is {(gl[i] ? "a loaded cell" : "a load hint")} but the reference has {(wl[i] ? "a loaded cell" : "a load hint")}: {Lists()}";
            }
        }

        if (got.Cells.Count != want.Cells.Count)
        {
            return $"candidates differ at position {n} ({(got.Cells.Count > n ? "an extra candidate" : "a missing candidate")}): {Lists()}";
        }

        if (got.Containing != want.Containing)
        {
            return $"containing cell {Cell(got.Containing)}, the reference's {Cell(want.Containing)}: {Lists()}";
        }

        if (got.HitsInteriorCell is bool gh && want.HitsInteriorCell is bool wh && gh != wh)
        {
            return $"HitsInteriorCell {gh}, the reference's {wh}: {Lists()}";
        }

        return null;
    }

    /// <summary>Shows a candidate list, load hints marked <c>(hint)</c>.</summary>
    /// <param name="r">An answer.</param>
    /// <returns>The text.</returns>
    public static string Show(FindCellResult r) =>
        string.Join(", ", r.Cells.Select((c, i) => CellIdText.Format(c) + (r.Loaded is { } l && !l[i] ? "(hint)" : string.Empty)));

    private static string Cell(CellId id) => id.IsNone ? "none" : CellIdText.Format(id);
}
