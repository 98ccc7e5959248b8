using AcPhys.Spec.Adapters;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;

namespace AcPhys.Cli.Replay;

/// <summary>
/// Replays a parts query (<c>kind: parts</c>): the parts, the cells the target answers, every parts invariant's
/// verdict (PARTS-COVERAGE, PARTS-SOUNDNESS), then the faults the file lists.
/// </summary>
internal sealed class PartsReplay : IReplayInput
{
    /// <inheritdoc/>
    public string Kind => "parts";

    /// <inheritdoc/>
    public string Description => "a parts / bounding-box query (the first part anchors)";

    /// <inheritdoc/>
    public int Replay(string path, ReplayTarget target)
    {
        var entry = CorpusJson.ReadFile(path);
        var parts = entry.Parts!;
        Terminal.Line($"replay {path}: {entry.Title}");
        Terminal.Line($"  kind parts, found by {entry.FoundBy}"
            + (entry.Invariant is null ? string.Empty : $", guards {entry.Invariant}")
            + (entry.Seed is null ? string.Empty : $", seed {entry.Seed}") + $", against {target.Impl.Name}");
        Terminal.Line($"  {parts}");
        if ((target.Impl.Ops & Op.OutsideCellsParts) == 0)
        {
            Terminal.Line($"replay: {target.Impl.Name} does not offer outside_cells_parts; nothing to check");
            return ExitCodes.Ok;
        }

        Terminal.Line($"  cells [{string.Join(", ", target.Impl.OutsideCellsParts(parts.Parts))}]");
        Terminal.Line();
        int violated = 0;
        foreach (var invariant in PartsInvariants.All)
        {
            var outcome = invariant.IsTestable(target.Impl) ? invariant.Check(target.Impl, parts) : (Outcome?)null;
            violated += outcome is { IsViolation: true } ? 1 : 0;
            string verdict = outcome is null ? "NOT TESTED" : outcome.Value.Verdict.ToString().ToUpperInvariant();
            string guarded = string.Equals(invariant.Id, entry.Invariant, StringComparison.OrdinalIgnoreCase) ? " (guarded)" : string.Empty;
            Terminal.Line($"  {invariant.Id + guarded,-28} {verdict}{(outcome is { IsViolation: true } o ? ": " + o.Message : string.Empty)}");
        }

        int caught = 0;
        foreach (var id in entry.Catches)
        {
            if (PlantedFaults.Find(id) is null)
            {
                throw new UsageException($"{path}: $.catches names unknown fault '{id}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
            }

            var hit = InvariantCatalogue.CheckParts(PlantedFaults.Create(id), parts);
            caught += hit is null ? 0 : 1;
            Terminal.Line($"  fault {id,-22} {(hit is null ? "NOT caught" : $"caught by {hit.InvariantId}")}");
        }

        Terminal.Line();
        Terminal.Line($"replay: {PartsInvariants.All.Count} parts invariants on {target.Impl.Name}: {violated} violated"
            + (entry.Catches.Count > 0 ? $"; listed faults caught: {caught}/{entry.Catches.Count}" : string.Empty));
        return violated == 0 ? ExitCodes.Ok : ExitCodes.Violated;
    }
}
