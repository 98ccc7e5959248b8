using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Running;

/// <summary>One root cause as a run sees it: every invariant failure whose shrunk case falls in the same failure class.</summary>
/// <param name="Cause">The failure class shared by the failures (e.g. <c>nonfinite</c>, <c>position:env</c>).</param>
/// <param name="Failures">The failures: invariant ID and shrunk violation, in catalogue order.</param>
public sealed record Finding(string Cause, IReadOnlyList<(string Invariant, Violation Violation)> Failures)
{
    /// <summary>Gets the IDs of the invariants this finding breaks.</summary>
    public IEnumerable<string> Invariants => Failures.Select(f => f.Invariant).Distinct();

    /// <summary>Gets the smallest shrunk case among the failures (shortest text), the one to read first.</summary>
    public (string Invariant, Violation Violation) Example => Failures.MinBy(f => f.Violation.CaseText.Length);
}

/// <summary>
/// Groups a run's failures into findings (issue #18): one root cause such as "NaN accepted" breaks several invariants,
/// each with its own shrunk case; failures whose shrunk cases share a failure class (the case's primary boundary class,
/// with the <c>centre:</c> prefix dropped so a LandDefs case and an outdoor query on the same kind of value meet) are one
/// finding that lists the invariants it breaks. Each invariant contributes its first failure and every further failure
/// class it found (<see cref="InvariantResult.MoreFailures"/>), so a second bug behind the first shows as a second finding.
/// </summary>
public static class Findings
{
    /// <summary>Groups failures into findings, most invariants first.</summary>
    /// <param name="results">A run's results.</param>
    /// <returns>The findings.</returns>
    public static IReadOnlyList<Finding> Of(IEnumerable<InvariantResult> results)
    {
        var groups = new Dictionary<string, List<(string, Violation)>>(StringComparer.Ordinal);
        var order = new List<string>();
        foreach (var r in results.Where(r => r.Status == ResultStatus.Failed && r.Violation is not null))
        {
            foreach (var (cls, v) in r.MoreFailures.Select(m => (m.Class, m.Violation)).Prepend((r.FailureClass ?? "unclassified", r.Violation!)))
            {
                string key = Cause(cls);
                if (!groups.TryGetValue(key, out var list))
                {
                    groups[key] = list = [];
                    order.Add(key);
                }

                list.Add((r.Invariant.Id, v));
            }
        }

        return [.. order.Select(k => new Finding(k, groups[k])).OrderByDescending(f => f.Invariants.Count())];
    }

    /// <summary>Returns the root-cause key of a failure class.</summary>
    /// <param name="failureClass">The class.</param>
    /// <returns>The key.</returns>
    public static string Cause(string failureClass) =>
        failureClass.StartsWith("centre:", StringComparison.Ordinal) ? failureClass["centre:".Length..] : failureClass;
}
