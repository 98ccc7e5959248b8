using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Corpus;

namespace AcPhys.Spec.Invariants;

/// <summary>The complete list of invariants: the only thing runners enumerate.</summary>
public static class InvariantCatalogue
{
    /// <summary>Gets every invariant, in catalogue order.</summary>
    public static IReadOnlyList<Invariant> All { get; } = [.. LandInvariants.All, .. OutdoorInvariants.All, .. WalkInvariants.All, .. PartsInvariants.All, .. IndoorInvariants.All, .. IndoorExactInvariants.All, .. ConformanceInvariants.All];

    /// <summary>Gets the scene invariants (over <see cref="SceneWalk"/>), conformance aside.</summary>
    public static IReadOnlyList<Invariant<SceneWalk>> SceneInvariants { get; } = [.. IndoorInvariants.All, .. IndoorExactInvariants.All];

    /// <summary>Gets the invariants over <see cref="LandCase"/>.</summary>
    public static IReadOnlyList<Invariant<LandCase>> Land => LandInvariants.All;

    /// <summary>Finds an invariant by ID (case-insensitive).</summary>
    /// <param name="id">The ID.</param>
    /// <returns>The invariant, or null.</returns>
    public static Invariant? Find(string id) => All.FirstOrDefault(i => string.Equals(i.Id, id, StringComparison.OrdinalIgnoreCase));

    /// <summary>Checks one case against every testable LandDefs invariant and returns the first violation.</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The case.</param>
    /// <returns>The first violation in catalogue order, or null when all hold.</returns>
    public static Violation? CheckLandCase(ICellPhysics impl, LandCase c)
    {
        foreach (var invariant in Land.Append(ConformanceInvariants.LandDefs))
        {
            if (!invariant.IsTestable(impl))
            {
                continue;
            }

            var outcome = invariant.Check(impl, c);
            if (outcome.IsViolation)
            {
                return new Violation(invariant.Id, outcome.Message ?? "violated", c.ToString()) { Case = c };
            }
        }

        return null;
    }

    /// <summary>
    /// Checks a walk: every testable walk invariant on the walk, then every testable outdoor invariant on the query
    /// of each step (as the reference answers them, so the queries are the ones a correct client would ask).
    /// </summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="walk">The walk.</param>
    /// <returns>The first violation, or null.</returns>
    public static Violation? CheckWalk(ICellPhysics impl, Walk walk)
    {
        foreach (var invariant in WalkInvariants.All)
        {
            if (invariant.IsTestable(impl) && invariant.Check(impl, walk) is { IsViolation: true } o)
            {
                return new Violation(invariant.Id, o.Message ?? "violated", walk.ToString()) { Case = walk };
            }
        }

        foreach (var step in WalkRunner.Run(ReferenceAdapter.Instance, walk))
        {
            foreach (var invariant in OutdoorInvariants.All.Append(ConformanceInvariants.OutsideCells))
            {
                if (invariant.IsTestable(impl) && invariant.Check(impl, step.Query) is { IsViolation: true } o)
                {
                    return new Violation(invariant.Id, $"step {step.Index}: {o.Message}", step.Query.ToString()) { Case = step.Query };
                }
            }
        }

        return CheckConformance(impl, new AnyWalk(walk, null));
    }

    /// <summary>Checks a corpus entry of any kind.</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="entry">The entry.</param>
    /// <returns>The first violation, or null.</returns>
    public static Violation? CheckEntry(ICellPhysics impl, CorpusEntry entry) =>
        entry.Parts is { } parts ? CheckParts(impl, parts) : entry.SceneWalk is { } sw ? CheckSceneWalk(impl, sw) : entry.Walk is { } walk ? CheckWalk(impl, walk) : CheckLandCase(impl, entry.Case!.Value);

    /// <summary>Checks a parts query against every testable parts invariant (PARTS-COVERAGE, PARTS-SOUNDNESS).</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The query.</param>
    /// <returns>The first violation in catalogue order, or null.</returns>
    public static Violation? CheckParts(ICellPhysics impl, PartsCase c)
    {
        foreach (var invariant in PartsInvariants.All)
        {
            if (invariant.IsTestable(impl) && invariant.Check(impl, c) is { IsViolation: true } o)
            {
                return new Violation(invariant.Id, o.Message ?? "violated", c.ToString()) { Case = c };
            }
        }

        return null;
    }

    /// <summary>Checks a scene walk against every testable scene invariant.</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="sw">The scene walk.</param>
    /// <returns>The first violation, or null.</returns>
    public static Violation? CheckSceneWalk(ICellPhysics impl, SceneWalk sw)
    {
        foreach (var invariant in SceneInvariants)
        {
            if (invariant.IsTestable(impl) && invariant.Check(impl, sw) is { IsViolation: true } o)
            {
                return new Violation(invariant.Id, o.Message ?? "violated", sw.ToString()) { Case = sw };
            }
        }

        return CheckConformance(impl, new AnyWalk(null, sw));
    }

    private static Violation? CheckConformance(ICellPhysics impl, AnyWalk w)
    {
        var invariant = ConformanceInvariants.FindCell;
        return invariant.IsTestable(impl) && invariant.Check(impl, w) is { IsViolation: true } o
            ? new Violation(invariant.Id, o.Message ?? "violated", w.ToString()) { Case = w.Inner }
            : null;
    }
}
