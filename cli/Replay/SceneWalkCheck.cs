using System.Globalization;
using System.Text.RegularExpressions;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Invariants;

namespace AcPhys.Cli.Replay;

/// <summary>
/// A scene walk run on one implementation: the step trace, every scene invariant's verdict, and each violation filed
/// under the step its message names (<c>step N: …</c>), or under the last step when the message names none.
/// </summary>
/// <param name="Trace">One record for the start query and one per step.</param>
/// <param name="PerStep">The violations filed under each step (same length as <paramref name="Trace"/>).</param>
/// <param name="Verdicts">Every scene invariant and its outcome, or null when not testable on the implementation.</param>
internal sealed partial record SceneWalkCheck(IReadOnlyList<WalkStep> Trace, IReadOnlyList<IReadOnlyList<Violation>> PerStep, IReadOnlyList<(Invariant Invariant, Outcome? Outcome)> Verdicts)
{
    /// <summary>Gets the index of the first step with a violation, or null.</summary>
    public int? FirstViolatingStep => PerStep.Select((v, i) => (v, i)).FirstOrDefault(t => t.v.Count > 0) is { v: not null } hit ? hit.i : null;

    /// <summary>Gets the number of invariants violated.</summary>
    public int ViolatedCount => Verdicts.Count(v => v.Outcome is { IsViolation: true });

    /// <summary>Runs the walk and checks every scene invariant.</summary>
    /// <param name="impl">The implementation; must offer find_cell_scene.</param>
    /// <param name="sw">The scene walk.</param>
    /// <returns>The check.</returns>
    public static SceneWalkCheck Run(ICellPhysics impl, SceneWalk sw)
    {
        var trace = SceneWalkRunner.Run(impl, sw);
        var perStep = trace.Select(_ => new List<Violation>()).ToList();
        var verdicts = new List<(Invariant, Outcome?)>();
        foreach (var invariant in InvariantCatalogue.SceneInvariants)
        {
            var outcome = invariant.IsTestable(impl) ? invariant.Check(impl, sw) : (Outcome?)null;
            verdicts.Add((invariant, outcome));
            if (outcome is { IsViolation: true } o)
            {
                int at = Math.Clamp(StepOf(o.Message) ?? (trace.Count - 1), 0, trace.Count - 1);
                perStep[at].Add(new Violation(invariant.Id, o.Message ?? "violated", sw.ToString()));
            }
        }

        return new SceneWalkCheck(trace, perStep, verdicts);
    }

    private static int? StepOf(string? message) =>
        message is not null && StepPattern().Match(message) is { Success: true } m ? int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture) : null;

    [GeneratedRegex(@"^step (\d+):")]
    private static partial Regex StepPattern();
}
