using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Invariants;
using Spectre.Console;

namespace AcPhys.Cli.Replay;

/// <summary>
/// Replays a corpus case (<c>kind: land</c>, docs/corpus-format.md): every LandDefs invariant on the case against the
/// target, then every fault the entry lists in <c>catches</c> against the case.
/// </summary>
internal sealed class LandCaseReplay : IReplayInput
{
    /// <inheritdoc/>
    public string Kind => "land";

    /// <inheritdoc/>
    public string Description => "a corpus case (one LandDefs input)";

    /// <inheritdoc/>
    public int Replay(string path, ReplayTarget target)
    {
        var entry = CorpusJson.ReadFile(path);
        Terminal.Line($"replay {path}: {entry.Title}");
        Terminal.Line($"  kind land, found by {entry.FoundBy}"
            + (entry.Invariant is null ? string.Empty : $", guards {entry.Invariant}")
            + (entry.Seed is null ? string.Empty : $", seed {entry.Seed}"));
        Terminal.Line($"  case {entry.Case}");
        if (entry.Invariant is not null && InvariantCatalogue.Find(entry.Invariant) is null)
        {
            Terminal.Line($"  note: the entry guards '{entry.Invariant}', which is not in the catalogue");
        }

        Terminal.Line();
        var landCase = entry.Case!.Value;
        var checks = InvariantCatalogue.Land.Select(i => (Invariant: i, Outcome: CheckOrSkip(i, target.Impl, landCase))).ToArray();
        WriteInvariants(checks, entry, target);

        var catches = entry.Catches.Select(id => Catch(id, landCase)).ToArray();
        if (catches.Length > 0)
        {
            Terminal.Line();
            WriteCatches(catches);
        }

        int holds = checks.Count(c => c.Outcome?.Verdict == Verdict.Holds);
        int vacuous = checks.Count(c => c.Outcome?.Verdict == Verdict.Vacuous);
        int violated = checks.Count(c => c.Outcome?.IsViolation == true);
        int notTested = checks.Count(c => c.Outcome is null);
        int caught = catches.Count(c => c.CaughtBy.Count > 0);
        var unknownFaults = catches.Where(c => c.Fault is null).Select(c => c.Id).ToArray();

        Terminal.Line();
        Terminal.Line($"replay: {checks.Length} invariants on {target.Impl.Name}: {holds} hold, {vacuous} vacuous, {violated} violated"
            + (notTested > 0 ? $", {notTested} not tested" : string.Empty)
            + (catches.Length > 0 ? $"; listed faults caught: {caught}/{catches.Length}" : string.Empty));

        if (unknownFaults.Length > 0)
        {
            throw new UsageException($"{path}: $.catches names unknown fault(s) {string.Join(", ", unknownFaults)} (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
        }

        return violated > 0 ? ExitCodes.Violated : ExitCodes.Ok;
    }

    private static Outcome? CheckOrSkip(Invariant<LandCase> invariant, ICellPhysics impl, LandCase c) =>
        invariant.IsTestable(impl) ? invariant.Check(impl, c) : null;

    private static FaultCatch Catch(string id, LandCase c)
    {
        var fault = PlantedFaults.Find(id);
        if (fault is null)
        {
            return new FaultCatch(id, null, []);
        }

        var impl = PlantedFaults.Create(fault.Id);
        var by = InvariantCatalogue.Land.Where(i => i.IsTestable(impl) && i.Check(impl, c).IsViolation).Select(i => i.Id).ToArray();
        return new FaultCatch(id, fault, by);
    }

    private static void WriteInvariants((Invariant<LandCase> Invariant, Outcome? Outcome)[] checks, CorpusEntry entry, ReplayTarget target)
    {
        var table = new Table().AddColumn("Invariant").AddColumn($"On {Markup.Escape(target.Impl.Name)}").AddColumn("Message");
        foreach (var (invariant, outcome) in checks)
        {
            bool guarded = string.Equals(invariant.Id, entry.Invariant, StringComparison.OrdinalIgnoreCase);
            string verdict = outcome switch
            {
                null => "[yellow]NOT TESTED[/]",
                { Verdict: Verdict.Holds } => "[green]HOLDS[/]",
                { Verdict: Verdict.Vacuous } => "[grey]VACUOUS[/]",
                _ => "[red bold]VIOLATED[/]",
            };
            table.AddRow(
                new Text(invariant.Id + (guarded ? " (guarded)" : string.Empty)),
                new Markup(verdict),
                new Text(outcome?.Message ?? (outcome is null ? "implementation lacks an operation it needs" : string.Empty)));
        }

        Terminal.Out.Write(table);
    }

    private static void WriteCatches(FaultCatch[] catches)
    {
        var table = new Table().AddColumn("Listed fault").AddColumn("Caught").AddColumn("By").AddColumn("Expected catchers");
        foreach (var c in catches)
        {
            string caught = c.Fault is null ? "[yellow]UNKNOWN FAULT[/]" : c.CaughtBy.Count > 0 ? "[green]CAUGHT[/]" : "[red bold]NOT CAUGHT[/]";
            table.AddRow(
                new Text(c.Id),
                new Markup(caught),
                new Text(c.CaughtBy.Count > 0 ? string.Join(", ", c.CaughtBy) : "-"),
                new Text(c.Fault is null ? "-" : string.Join(", ", c.Fault.CaughtBy)));
        }

        Terminal.Out.Write(table);
    }

    private sealed record FaultCatch(string Id, PlantedFault? Fault, IReadOnlyList<string> CaughtBy);
}
