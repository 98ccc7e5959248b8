using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;
using FsCheck;
using FsCheck.Fluent;

namespace AcPhys.Spec.Judging;

/// <summary>
/// Which declaration would make a conformance finding intended (issue #29, actionable findings; proved, issue 41): the
/// failing case is judged again with the implementation's answers unchanged but one more documented deviation declared
/// (each fidelity switch, then <c>ace</c>) or the other pick policy. A declaration is named only when the answers equal
/// the reference's in that mode on the shrunk case, the original case, <see cref="FreshCases"/> fresh cases of the
/// shrunk case's class and <see cref="OtherClassCases"/> fresh cases of every other class drawn; otherwise what differs
/// is said. The other classes matter: a port that skips the indoor visibility filter always answers like
/// <c>ace-early-return</c> (facts §7 #7: the filter skipped after an interior pick) on every interior pick, and differs only
/// where the pick is not interior — a declaration that explains one class but not the invariant's whole domain would
/// excuse more than its deviation. A port bug that only reorders or only adds cells is never called intended.
/// </summary>
public static class IntendedUnder
{
    /// <summary>How many fresh cases of the failing case's class a declaration must also explain.</summary>
    public const int FreshCases = 12;

    /// <summary>How many fresh cases of each other class drawn a declaration must also explain.</summary>
    public const int OtherClassCases = 2;

    // How many cases are drawn to find the fresh cases of one class.
    private const int Draws = 600;

    /// <summary>Returns the declaration (as a port writes it in <c>hello</c>) under which the case conforms, or null.</summary>
    /// <param name="impl">The implementation, still answering.</param>
    /// <param name="invariantId">The failing invariant.</param>
    /// <param name="cases">Its failing cases: the shrunk one and the original (a shrunk case alone is often explained by
    /// several switches; a declaration is named only when it explains every one, and fresh cases of the shrunk case's class).</param>
    /// <returns>E.g. <c>"fidelity": ["ace-transition-filter"]</c>, or null (also for invariants other than conformance).</returns>
    public static string? Find(ICellPhysics impl, string invariantId, IReadOnlyList<AnyCase> cases) => Explain(impl, invariantId, cases)?.Declaration;

    /// <summary>Explains a conformance finding: the declaration that makes it intended, proved on fresh cases, or what differs.</summary>
    /// <param name="impl">The implementation, still answering.</param>
    /// <param name="invariantId">The failing invariant.</param>
    /// <param name="cases">The shrunk case first, then the original.</param>
    /// <returns>Null for a case that is not a conformance finding (or does not fail as it is); else the explanation.</returns>
    public static Intent? Explain(ICellPhysics impl, string invariantId, IReadOnlyList<AnyCase> cases)
    {
        if (cases.Count == 0 || cases.Any(c => Rejudge(impl, invariantId, c) is not { IsViolation: true }))
        {
            return null; // not a conformance finding, or it does not fail as it is
        }

        string? nearest = null;
        foreach (var (label, declared) in Declarations(impl))
        {
            try
            {
                if (!cases.All(c => Rejudge(declared, invariantId, c) is { Verdict: Verdict.Holds }))
                {
                    continue;
                }

                var (same, others) = Fresh(invariantId, cases[0]);
                var broken = same.Select(c => (Case: c, Outcome: Rejudge(declared, invariantId, c))).FirstOrDefault(x => x.Outcome is { IsViolation: true });
                var elsewhere = broken.Outcome is null && same.Count > 0
                    ? others.Select(c => (Case: c, Outcome: Rejudge(declared, invariantId, c))).FirstOrDefault(x => x.Outcome is { IsViolation: true })
                    : default;
                if (same.Count > 0 && broken.Outcome is null && elsewhere.Outcome is null)
                {
                    return new Intent(label, null);
                }

                nearest ??= same.Count == 0
                    ? $"declaring {label} explains this case, but no fresh case of its class was drawn to prove it"
                    : broken.Outcome is { } b
                    ? $"declaring {label} explains this case but not a fresh case of its class: {b.Message}"
                    : $"declaring {label} explains this case and its class but not a case of another class: {elsewhere.Outcome!.Value.Message}";
            }
            catch (AdapterFailureException)
            {
                return new Intent(null, "the implementation stopped answering while the declarations were tried");
            }
        }

        return new Intent(null, nearest ?? "no documented deviation or pick explains these answers: a departure from retail (and from ACE), a port bug or an undocumented difference");
    }

    // The implementation's own declaration plus one switch each (indoor switches, double, then ace), then the other pick.
    private static IEnumerable<(string Label, ICellPhysics Declared)> Declarations(ICellPhysics impl)
    {
        var own = FidelityNames.Names(impl.Indoor, impl.Outdoor);
        foreach (var name in FidelityNames.Known.Skip(2).Append(FidelityNames.Double).Append(FidelityNames.Ace).Where(n => !own.Contains(n)))
        {
            if (FidelityNames.TryParse(own.Append(name), out var indoor, out var outdoor, out _) && (indoor != impl.Indoor || outdoor != impl.Outdoor))
            {
                yield return ($"\"fidelity\": [{string.Join(", ", own.Append(name).Select(n => $"\"{n}\""))}]", new OpsOffered(impl, impl.Ops) { Indoor = indoor, Outdoor = outdoor });
            }
        }

        var other = impl.Pick == PickPolicy.Retail ? PickPolicy.CurrentFirst : PickPolicy.Retail;
        yield return ($"\"pick\": \"{PickNames.Of(other)}\"", new OpsOffered(impl, impl.Ops) { Pick = other });
    }

    // Fresh cases of the shrunk case's class (its domain's primary class) and a few of every other class drawn, with a
    // fixed seed.
    private static (List<AnyCase> Same, List<AnyCase> Others) Fresh(string id, AnyCase like)
    {
        const ulong seed = 0x41_41_41_41UL; // fixed: the same finding is explained the same way every run
        return (id, like) switch
        {
            ("FIND-CELL-CONFORMANCE", AnyCase.WalkInScene sw) => Spread(AnyWalkDomain.Instance, new AnyWalk(null, sw.Walk), seed, w => w.Indoor is { } i ? (AnyCase)i : w.Outdoor!),
            ("FIND-CELL-CONFORMANCE", AnyCase.OutdoorWalk w) => Spread(AnyWalkDomain.Instance, new AnyWalk(w.Walk, null), seed, x => x.Indoor is { } i ? (AnyCase)i : x.Outdoor!),
            ("FIND-CELL-QUERY-CONFORMANCE" or "OUTSIDE-CELLS-CONFORMANCE", AnyCase.OutdoorQuery q) => Spread(OutdoorDomain.Instance, q.Query, seed, c => c),
            ("LANDDEFS-CONFORMANCE", AnyCase.LandQuery l) => Spread(LandDomain.Instance, l.Case, seed, c => c),
            ("PARTS-INDOOR-CONFORMANCE", AnyCase.WalkInScene sw) => Spread(SceneDomain.Instance, sw.Walk, seed, w => w),
            _ => ([], []),
        };
    }

    private static (List<AnyCase> Same, List<AnyCase> Others) Spread<T>(ICaseDomain<T> domain, T like, ulong seed, Func<T, AnyCase> asCase)
    {
        string cls = domain.Primary(like);
        var drawn = Gen.Sample(domain.Arbitrary.Generator, Draws, new Rnd(seed, 0x9E3779B97F4A7C15UL), 50).ToList();
        var same = drawn.Where(c => domain.Primary(c) == cls).Take(FreshCases).Select(asCase).ToList();
        var others = drawn.GroupBy(domain.Primary).Where(g => g.Key != cls).OrderBy(g => g.Key, StringComparer.Ordinal)
            .SelectMany(g => g.Take(OtherClassCases)).Select(asCase).ToList();
        return (same, others);
    }

    private static AcPhys.Spec.Invariants.Outcome? Rejudge(ICellPhysics impl, string id, AnyCase c) => (id, c) switch
    {
        ("FIND-CELL-CONFORMANCE", AnyCase.WalkInScene sw) => ConformanceInvariants.FindCell.Check(impl, new AnyWalk(null, sw.Walk)),
        ("FIND-CELL-CONFORMANCE", AnyCase.OutdoorWalk w) => ConformanceInvariants.FindCell.Check(impl, new AnyWalk(w.Walk, null)),
        ("FIND-CELL-QUERY-CONFORMANCE", AnyCase.OutdoorQuery q) => ConformanceInvariants.FindCellQuery.Check(impl, q.Query),
        ("OUTSIDE-CELLS-CONFORMANCE", AnyCase.OutdoorQuery q) => ConformanceInvariants.OutsideCells.Check(impl, q.Query),
        ("LANDDEFS-CONFORMANCE", AnyCase.LandQuery l) => ConformanceInvariants.LandDefs.Check(impl, l.Case),
        ("PARTS-INDOOR-CONFORMANCE", AnyCase.WalkInScene sw) => PartsIndoorInvariants.Conformance.Check(impl, sw.Walk),
        _ => null,
    };
}

/// <summary>What <see cref="IntendedUnder.Explain"/> found: the declaration that makes a finding intended, or what differs.</summary>
/// <param name="Declaration">The declaration as a port writes it in <c>hello</c>, proved on fresh cases; null when none is.</param>
/// <param name="Differs">When no declaration is named: why (the nearest declaration and the fresh case it fails, or that none explains the answers).</param>
public sealed record Intent(string? Declaration, string? Differs);
