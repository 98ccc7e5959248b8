using AcPhys.Core;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Judging;

/// <summary>
/// Which declaration would make a conformance finding intended (issue #29, actionable findings): the failing case is
/// judged again with the implementation's answers unchanged but one more documented deviation declared (each fidelity
/// switch, then <c>ace</c>) or the other pick policy, and the first declaration under which the answers equal the
/// reference's in that mode, on the shrunk case and the original alike, is named. Null when none does: the finding is a plain departure from retail.
/// </summary>
public static class IntendedUnder
{
    /// <summary>Returns the declaration (as a port writes it in <c>hello</c>) under which the case conforms, or null.</summary>
    /// <param name="impl">The implementation, still answering.</param>
    /// <param name="invariantId">The failing invariant.</param>
    /// <param name="cases">Its failing cases: the shrunk one and the original (a shrunk case alone is often explained by
    /// several switches; a declaration is named only when it explains every one).</param>
    /// <returns>E.g. <c>"fidelity": ["ace-transition-filter"]</c>, or null (also for invariants other than conformance).</returns>
    public static string? Find(ICellPhysics impl, string invariantId, IReadOnlyList<AnyCase> cases)
    {
        if (cases.Count == 0 || cases.Any(c => Rejudge(impl, invariantId, c) is not { IsViolation: true }))
        {
            return null; // not a conformance finding, or it does not fail as it is
        }

        foreach (var (label, declared) in Declarations(impl))
        {
            try
            {
                if (cases.All(c => Rejudge(declared, invariantId, c) is { Verdict: Verdict.Holds }))
                {
                    return label;
                }
            }
            catch (AdapterFailureException)
            {
                return null; // the implementation stopped answering: nothing more to learn
            }
        }

        return null;
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

    private static Outcome? Rejudge(ICellPhysics impl, string id, AnyCase c) => (id, c) switch
    {
        ("FIND-CELL-CONFORMANCE", AnyCase.WalkInScene sw) => ConformanceInvariants.FindCell.Check(impl, new AnyWalk(null, sw.Walk)),
        ("FIND-CELL-CONFORMANCE", AnyCase.OutdoorWalk w) => ConformanceInvariants.FindCell.Check(impl, new AnyWalk(w.Walk, null)),
        ("FIND-CELL-QUERY-CONFORMANCE", AnyCase.OutdoorQuery q) => ConformanceInvariants.FindCellQuery.Check(impl, q.Query),
        ("OUTSIDE-CELLS-CONFORMANCE", AnyCase.OutdoorQuery q) => ConformanceInvariants.OutsideCells.Check(impl, q.Query),
        ("LANDDEFS-CONFORMANCE", AnyCase.LandQuery l) => ConformanceInvariants.LandDefs.Check(impl, l.Case),
        _ => null,
    };
}
