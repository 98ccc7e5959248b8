using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Invariants;

namespace AcPhys.E2E.Support;

/// <summary>The summary line a clean run prints, counted from the catalogue: what an implementation with these ops and this pick can be tested on.</summary>
internal static class Expected
{
    /// <summary>Returns "verify: N invariants, P passed, 0 failed, T not tested" for a clean implementation.</summary>
    /// <param name="ops">The ops it offers.</param>
    /// <param name="pick">The pick it declares.</param>
    /// <returns>The line's text.</returns>
    public static string CleanSummary(Op ops, PickPolicy pick = PickPolicy.Retail)
    {
        int total = InvariantCatalogue.All.Count;
        int testable = InvariantCatalogue.All.Count(i => i.WhyNotTestable(ops, pick) is null);
        return $"verify: {total} invariants, {testable} passed, 0 failed, {total - testable} not tested";
    }
}
