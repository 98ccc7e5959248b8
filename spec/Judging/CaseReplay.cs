using AcPhys.Contract;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Faults;

namespace AcPhys.Spec.Judging;

/// <summary>
/// Replays a stored case (a corpus file, a failure file, a fuzz finding, a diff case file): the case run and judged on
/// the target, then each fault the entry lists judged on the case. <c>acphys replay</c> and <c>render</c> print this.
/// </summary>
/// <param name="Entry">The entry.</param>
/// <param name="Run">The case run on the target.</param>
/// <param name="Catches">One per fault the entry lists.</param>
public sealed record CaseReplay(CorpusEntry Entry, CaseRun Run, IReadOnlyList<FaultCatch> Catches)
{
    /// <summary>The exit code when every judge held or was vacuous.</summary>
    public const int Holds = 0;

    /// <summary>The exit code when some judge was violated.</summary>
    public const int Violated = 1;

    /// <summary>Gets the exit code: <see cref="Violated"/> when the target violates an invariant, else <see cref="Holds"/>.</summary>
    public int ExitCode => Run.Judgement.IsViolation ? Violated : Holds;

    /// <summary>Gets the fault ids the entry lists that are not planted faults.</summary>
    public IReadOnlyList<string> UnknownFaults => [.. Catches.Where(c => c.Fault is null).Select(c => c.Id)];

    /// <summary>Replays an entry on a target.</summary>
    /// <param name="entry">The entry.</param>
    /// <param name="target">The implementation.</param>
    /// <returns>The replay.</returns>
    /// <exception cref="AdapterFailureException">The implementation could not answer at all.</exception>
    public static CaseReplay Of(CorpusEntry entry, ICellPhysics target)
    {
        var run = CaseRun.Of(target, entry.Item);
        var catches = entry.Catches.Select(id => PlantedFaults.Find(id) is { } fault
            ? new FaultCatch(id, fault, Judges.Judge(PlantedFaults.Create(fault.Id), entry.Item).ViolatedIds)
            : new FaultCatch(id, null, [])).ToList();
        return new CaseReplay(entry, run, catches);
    }

    /// <summary>Tests whether a stored case reproduces its finding: the target violates the invariant the entry guards (any invariant when it names none).</summary>
    /// <param name="entry">The entry.</param>
    /// <param name="target">The implementation the finding was made on.</param>
    /// <returns>True when it reproduces.</returns>
    /// <exception cref="AdapterFailureException">The implementation could not answer at all.</exception>
    public static bool Reproduces(CorpusEntry entry, ICellPhysics target)
    {
        var ids = Judges.Judge(target, entry.Item).ViolatedIds;
        return entry.Invariant is null ? ids.Count > 0 : ids.Contains(entry.Invariant, StringComparer.OrdinalIgnoreCase);
    }
}
