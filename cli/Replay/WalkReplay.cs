using System.Globalization;
using System.Text.RegularExpressions;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;

namespace AcPhys.Cli.Replay;

/// <summary>
/// Replays a walk file (<c>kind: walk</c>): runs it step by step against the target, prints a step table (position,
/// cells, containing cell, invariants checked) and the first violating step; then the faults the file lists.
/// </summary>
internal sealed partial class WalkReplay : IReplayInput
{
    /// <inheritdoc/>
    public string Kind => "walk";

    /// <inheritdoc/>
    public string Description => "a walk (start, body, steps)";

    /// <summary>Checks a walk against an implementation: per-step outdoor invariants and whole-walk invariants.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="walk">The walk.</param>
    /// <returns>The trace, the violations per step, and the whole-walk outcomes.</returns>
    public static WalkCheck Check(ICellPhysics impl, Walk walk)
    {
        var trace = WalkRunner.Run(impl, walk);
        var perStep = trace.Select(step => OutdoorInvariants.All
            .Where(i => i.IsTestable(impl))
            .Select(i => (i.Id, Outcome: i.Check(impl, step.Query)))
            .Where(t => t.Outcome.IsViolation)
            .Select(t => new Violation(t.Id, t.Outcome.Message ?? "violated", step.Query.ToString()))
            .ToList()).ToList();
        var whole = WalkInvariants.All.Select(i => (Invariant: (Invariant)i, Outcome: i.IsTestable(impl) ? i.Check(impl, walk) : (Outcome?)null)).ToList();
        foreach (var (invariant, outcome) in whole)
        {
            if (outcome is { IsViolation: true } o)
            {
                int at = StepOf(o.Message) ?? trace.Count - 1;
                perStep[Math.Clamp(at, 0, perStep.Count - 1)].Add(new Violation(invariant.Id, o.Message ?? "violated", walk.ToString()));
            }
        }

        return new WalkCheck(trace, perStep, whole);
    }

    /// <inheritdoc/>
    public int Replay(string path, ReplayTarget target)
    {
        var entry = CorpusJson.ReadFile(path);
        var walk = entry.Walk!;
        Terminal.Line($"replay {path}: {entry.Title}");
        Terminal.Line($"  kind walk, found by {entry.FoundBy}"
            + (entry.Invariant is null ? string.Empty : $", guards {entry.Invariant}")
            + (entry.Seed is null ? string.Empty : $", seed {entry.Seed}") + $", against {target.Impl.Name} (pick {PickNames.Of(target.Impl.Pick)})");
        Terminal.Line($"  {walk}");
        Terminal.Line();

        var check = Check(target.Impl, walk);
        string checkedIds = string.Join(", ", OutdoorInvariants.All.Where(i => i.IsTestable(target.Impl)).Select(i => i.Id));
        Terminal.Line($"  per step: {checkedIds}");
        Terminal.Line($"  {"step",4}  {"frame",-10}  {"position (block frame)",-26}  {"containing",-10}  {"current",-10}  cells / violations");
        foreach (var step in check.Trace)
        {
            var bad = check.PerStep[step.Index];
            Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"  {step.Index,4}  {step.Frame,-10}  {"(" + FloatText.Format(step.Position.X) + ", " + FloatText.Format(step.Position.Y) + ")",-26}  {step.Containing,-10}  {step.Current,-10}  [{string.Join(", ", step.Cells)}]"));
            foreach (var v in bad)
            {
                Terminal.Line($"  {string.Empty,4}  VIOLATED {v.InvariantId}: {v.Message}");
            }
        }

        Terminal.Line();
        foreach (var (invariant, outcome) in check.Whole)
        {
            string verdict = outcome is null ? "NOT TESTED" : outcome.Value.Verdict.ToString().ToUpperInvariant();
            Terminal.Line($"  {invariant.Id,-20} {verdict}{(outcome is { IsViolation: true } o ? ": " + o.Message : string.Empty)}");
        }

        int? first = check.FirstViolatingStep;
        int caught = 0;
        foreach (var id in entry.Catches)
        {
            if (PlantedFaults.Find(id) is null)
            {
                throw new UsageException($"{path}: $.catches names unknown fault '{id}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
            }

            var faulty = Check(PlantedFaults.Create(id), walk);
            bool hit = faulty.FirstViolatingStep is not null;
            caught += hit ? 1 : 0;
            Terminal.Line($"  fault {id,-20} {(hit ? $"caught at step {faulty.FirstViolatingStep}" : "NOT caught")}");
        }

        Terminal.Line();
        Terminal.Line($"replay: {check.Trace.Count - 1} steps on {target.Impl.Name}: "
            + (first is int f ? $"first violation at step {f} ({string.Join(", ", check.PerStep[f].Select(v => v.InvariantId).Distinct())})" : "no violation")
            + (entry.Catches.Count > 0 ? $"; listed faults caught: {caught}/{entry.Catches.Count}" : string.Empty));
        return first is null ? ExitCodes.Ok : ExitCodes.Violated;
    }

    private static int? StepOf(string? message) =>
        message is not null && StepPattern().Match(message) is { Success: true } m ? int.Parse(m.Groups[1].Value, CultureInfo.InvariantCulture) : null;

    [GeneratedRegex(@"^step (\d+):")]
    private static partial Regex StepPattern();
}

/// <summary>The result of checking a walk.</summary>
/// <param name="Trace">The steps.</param>
/// <param name="PerStep">Violations attributed to each step.</param>
/// <param name="Whole">Whole-walk invariants and their outcomes (null: not tested).</param>
internal sealed record WalkCheck(IReadOnlyList<WalkStep> Trace, IReadOnlyList<List<Violation>> PerStep, IReadOnlyList<(Invariant Invariant, Outcome? Outcome)> Whole)
{
    /// <summary>Gets the first step with a violation, or null.</summary>
    public int? FirstViolatingStep => PerStep.Select((v, i) => (v, i)).FirstOrDefault(t => t.v.Count > 0) is { v: not null } hit ? hit.i : null;
}
