using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;

namespace AcPhys.Spec.Invariants;

/// <summary>The complete list of invariants: the only thing runners enumerate.</summary>
public static class InvariantCatalogue
{
    /// <summary>Gets every invariant, in catalogue order.</summary>
    public static IReadOnlyList<Invariant> All { get; } = [.. LandInvariants.All];

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
        foreach (var invariant in Land)
        {
            if (!invariant.IsTestable(impl))
            {
                continue;
            }

            var outcome = invariant.Check(impl, c);
            if (outcome.IsViolation)
            {
                return new Violation(invariant.Id, outcome.Message ?? "violated", c.ToString());
            }
        }

        return null;
    }
}
