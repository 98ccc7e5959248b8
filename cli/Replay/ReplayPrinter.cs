using System.Globalization;
using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Judging;

namespace AcPhys.Cli.Replay;

/// <summary>
/// Prints a stored case's replay (<see cref="CaseReplay"/>, judged in the library by <see cref="Judges"/>): the case, the
/// implementation's steps with each violation under its step (walks and scene walks), every judge's verdict, the faults
/// the file lists, and a summary line naming what was violated.
/// </summary>
internal static class ReplayPrinter
{
    /// <summary>Replays an entry and prints the report.</summary>
    /// <param name="entry">The entry (from a file or a record folder).</param>
    /// <param name="path">Where it came from, for messages.</param>
    /// <param name="target">What to check against.</param>
    /// <returns>The exit code: 0 every judge held or was vacuous, 1 some judge was violated.</returns>
    /// <exception cref="UsageException">The entry lists an unknown fault.</exception>
    public static int Replay(CorpusEntry entry, string path, ReplayTarget target)
    {
        var impl = target.Impl;
        Terminal.Line($"replay {path}: {entry.Title}");
        Terminal.Line($"  kind {entry.Kind}, found by {entry.FoundBy}"
            + (entry.Invariant is null ? string.Empty : $", guards {entry.Invariant}")
            + (entry.Seed is null ? string.Empty : $", seed {entry.Seed}") + $", against {impl.Name} (pick {PickNames.Of(impl.Pick)})");
        if (entry.Invariant is not null && AcPhys.Spec.Invariants.InvariantCatalogue.Find(entry.Invariant) is null)
        {
            Terminal.Line($"  note: the entry guards '{entry.Invariant}', which is not in the catalogue (a diff check's id, or an older file): every judge of its kind is asked");
        }

        WriteCase(entry.Item, impl);
        Terminal.Line();
        var replay = CaseReplay.Of(entry, impl);
        var run = replay.Run;
        WriteSteps(entry.Item, run);
        foreach (var v in run.Judgement.Verdicts)
        {
            string guarded = string.Equals(v.Invariant.Id, entry.Invariant, StringComparison.OrdinalIgnoreCase) ? " (guarded)" : string.Empty;
            string verdict = v.Outcome is null ? "NOT TESTED" : v.Outcome.Value.Verdict.ToString().ToUpperInvariant();
            string why = v.IsViolation ? v.Outcome!.Value.Message ?? "violated" : v.Reason ?? string.Empty;
            Terminal.Line($"  {verdict} {v.Invariant.Id}{guarded}{(why.Length > 0 ? ": " + why : string.Empty)}");
        }

        foreach (var c in replay.Catches.Where(c => c.Fault is not null))
        {
            Terminal.Line($"  fault {c.Id,-22} {(c.CaughtBy.Count > 0 ? $"caught by {string.Join(", ", c.CaughtBy)}" : "NOT caught")} (expected catchers: {string.Join(", ", c.Fault!.CaughtBy)})");
        }

        var verdicts = run.Judgement.Verdicts;
        int holds = verdicts.Count(v => v.Outcome?.Verdict == AcPhys.Spec.Invariants.Verdict.Holds);
        int vacuous = verdicts.Count(v => v.Outcome?.Verdict == AcPhys.Spec.Invariants.Verdict.Vacuous);
        int notTested = verdicts.Count(v => v.Outcome is null);
        var violated = run.Judgement.ViolatedIds;
        int caught = replay.Catches.Count(c => c.CaughtBy.Count > 0);
        Terminal.Line();
        Terminal.Line($"replay: {verdicts.Count} invariants on {impl.Name}"
            + (run.Trace.Count > 0 ? $" ({run.Trace.Count - 1} steps)" : string.Empty)
            + $": {holds} hold, {vacuous} vacuous, {violated.Count} violated"
            + (notTested > 0 ? $", {notTested} not tested" : string.Empty)
            + (violated.Count > 0 ? $" ({string.Join(", ", violated)})" : string.Empty)
            + (run.Trace.Count > 0 && run.FirstViolatingStep is int f ? $", first at step {f} ({string.Join(", ", run.PerStep[f].Select(v => v.InvariantId).Distinct())})" : string.Empty)
            + (replay.Catches.Count > 0 ? $"; listed faults caught: {caught}/{replay.Catches.Count}" : string.Empty));

        if (replay.UnknownFaults.Count > 0)
        {
            throw new UsageException($"{path}: $.catches names unknown fault(s) {string.Join(", ", replay.UnknownFaults)} (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
        }

        return replay.ExitCode;
    }

    private static void WriteCase(AnyCase c, ICellPhysics impl)
    {
        foreach (string line in c.Match<string[]>(
            land => [$"  case {land.Case}"],
            q => [$"  query {q.Query}"],
            w => [$"  {w.Walk}"],
            sw => [$"  {sw.Walk.Scene}", $"  {sw.Walk.Size}"],
            p => (impl.Ops & Op.OutsideCellsParts) != 0 ? [$"  {p.Parts}", $"  cells [{string.Join(", ", impl.OutsideCellsParts(p.Parts.Parts))}]"] : [$"  {p.Parts}"]))
        {
            Terminal.Line(line);
        }
    }

    private static void WriteSteps(AnyCase c, CaseRun run)
    {
        if (run.Trace.Count == 0)
        {
            return;
        }

        bool scene = c is AnyCase.WalkInScene;
        Terminal.Line(scene
            ? $"  {"step",4}  {"cell",-10}  {"position (block frame)",-34}  {"containing",-10}  {"current",-10}  candidates / violations"
            : $"  {"step",4}  {"frame",-10}  {"position (block frame)",-26}  {"containing",-10}  {"current",-10}  cells / violations");
        foreach (var step in run.Trace)
        {
            string position = scene
                ? $"{"(" + FloatText.Format(step.Position.X) + ", " + FloatText.Format(step.Position.Y) + ", " + FloatText.Format(step.Position.Z) + ")",-34}"
                : $"{"(" + FloatText.Format(step.Position.X) + ", " + FloatText.Format(step.Position.Y) + ")",-26}";
            Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"  {step.Index,4}  {step.Frame,-10}  {position}  {step.Containing,-10}  {step.Current,-10}  [{string.Join(", ", step.Cells)}]"));
            foreach (var v in run.PerStep[step.Index])
            {
                Terminal.Line($"  {string.Empty,4}  VIOLATED {v.InvariantId}: {v.Message}");
            }
        }

        Terminal.Line();
    }
}
