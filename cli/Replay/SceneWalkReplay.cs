using System.Globalization;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;

namespace AcPhys.Cli.Replay;

/// <summary>
/// Replays a scene walk (<c>kind: scene-walk</c>): the scene in one line, a step table (frame, position, containing,
/// current, candidates) with each violation under the step it names, every scene invariant's verdict, then the faults the
/// file lists. <c>acphys render</c> draws the same walk (<see cref="Render.SceneSvg"/>).
/// </summary>
internal sealed class SceneWalkReplay : IReplayInput
{
    /// <inheritdoc/>
    public string Kind => "scene-walk";

    /// <inheritdoc/>
    public string Description => "a walk in a scene (loaded blocks, buildings, env cells, portals)";

    /// <inheritdoc/>
    public int Replay(string path, ReplayTarget target) => Replay(CaseFiles.Read(path), path, target);

    /// <summary>Replays an entry already read (from a corpus file or a record folder).</summary>
    /// <param name="entry">The entry (kind scene-walk).</param>
    /// <param name="path">Where it came from, for messages.</param>
    /// <param name="target">What to check against.</param>
    /// <returns>The exit code.</returns>
    public static int Replay(CorpusEntry entry, string path, ReplayTarget target)
    {
        var sw = entry.SceneWalk!;
        Terminal.Line($"replay {path}: {entry.Title}");
        Terminal.Line($"  kind scene-walk, found by {entry.FoundBy}"
            + (entry.Invariant is null ? string.Empty : $", guards {entry.Invariant}")
            + (entry.Seed is null ? string.Empty : $", seed {entry.Seed}") + $", against {target.Impl.Name} (pick {PickNames.Of(target.Impl.Pick)})");
        Terminal.Line($"  {sw.Scene}");
        Terminal.Line($"  {sw.Size}");
        Terminal.Line();
        if ((target.Impl.Ops & Op.FindCellScene) == 0)
        {
            Terminal.Line($"replay: {target.Impl.Name} does not offer find_cell_scene; nothing to check");
            return ExitCodes.Ok;
        }

        var check = SceneWalkCheck.Run(target.Impl, sw);
        Terminal.Line($"  {"step",4}  {"cell",-10}  {"position (block frame)",-34}  {"containing",-10}  {"current",-10}  candidates / violations");
        foreach (var step in check.Trace)
        {
            Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"  {step.Index,4}  {step.Frame,-10}  {"(" + FloatText.Format(step.Position.X) + ", " + FloatText.Format(step.Position.Y) + ", " + FloatText.Format(step.Position.Z) + ")",-34}  {step.Containing,-10}  {step.Current,-10}  [{string.Join(", ", step.Cells)}]"));
            foreach (var v in check.PerStep[step.Index])
            {
                Terminal.Line($"  {string.Empty,4}  VIOLATED {v.InvariantId}: {v.Message}");
            }
        }

        Terminal.Line();
        foreach (var (invariant, outcome) in check.Verdicts)
        {
            string verdict = outcome is null ? "NOT TESTED" : outcome.Value.Verdict.ToString().ToUpperInvariant();
            Terminal.Line($"  {invariant.Id,-20} {verdict}{(outcome is { IsViolation: true } o ? ": " + o.Message : string.Empty)}");
        }

        int caught = 0;
        foreach (var id in entry.Catches)
        {
            if (PlantedFaults.Find(id) is null)
            {
                throw new UsageException($"{path}: $.catches names unknown fault '{id}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
            }

            var hit = InvariantCatalogue.CheckSceneWalk(PlantedFaults.Create(id), sw);
            caught += hit is null ? 0 : 1;
            Terminal.Line($"  fault {id,-22} {(hit is null ? "NOT caught" : $"caught by {hit.InvariantId}")}");
        }

        Terminal.Line();
        int violated = check.ViolatedCount;
        Terminal.Line($"replay: {check.Trace.Count - 1} steps on {target.Impl.Name}: "
            + (check.FirstViolatingStep is int f ? $"{violated} invariant(s) violated, first at step {f} ({string.Join(", ", check.PerStep[f].Select(v => v.InvariantId).Distinct())})" : "no violation")
            + (entry.Catches.Count > 0 ? $"; listed faults caught: {caught}/{entry.Catches.Count}" : string.Empty));
        return violated == 0 ? ExitCodes.Ok : ExitCodes.Violated;
    }
}
