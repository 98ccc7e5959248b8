using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Protocol.Client;
using AcPhys.Spec.Generators;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Judging;

namespace AcPhys.Fuzz.Targets;

/// <summary>
/// A physics target: a total codec turns any bytes into a bounded, valid <typeparamref name="TCase"/> (so every input
/// reaches the physics, never a parser), every relevant invariant of the catalogue is checked on it, and a broken one
/// throws <see cref="InvariantViolationException"/> carrying the invariant ID. Crashes are shrunk with the same
/// shrinker the properties use.
/// </summary>
/// <typeparam name="TCase">The case type (one the corpus format stores).</typeparam>
public abstract class PhysicsTarget<TCase> : FuzzTarget
    where TCase : notnull
{
    /// <summary>Most shrink candidates tried per finding.</summary>
    public const int ShrinkBudget = 20_000;

    /// <inheritdoc/>
    public sealed override TargetKind Kind => TargetKind.Physics;

    /// <summary>Decodes bytes into a case; total (never throws).</summary>
    /// <param name="data">Any bytes.</param>
    /// <returns>The case.</returns>
    public abstract TCase Decode(ReadOnlySpan<byte> data);

    /// <summary>Checks every relevant invariant on a case.</summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The case.</param>
    /// <returns>The first violation, or null.</returns>
    public abstract Violation? Check(ICellPhysics impl, TCase c);

    /// <summary>Runs a case through the reference's physics once, judging nothing: the limit <see cref="CreatePhysicsOnly"/> times.</summary>
    /// <param name="c">The case.</param>
    /// <returns>The answer (returned so that nothing of the run is left out).</returns>
    public abstract object Physics(TCase c);

    /// <inheritdoc/>
    public sealed override Action<ReadOnlySpan<byte>>? CreatePhysicsOnly() => data => GC.KeepAlive(Physics(Decode(data)));

    /// <summary>Returns simpler candidates (the properties' shrinker).</summary>
    /// <param name="c">The case.</param>
    /// <returns>Candidates.</returns>
    public abstract IEnumerable<TCase> Shrink(TCase c);

    /// <summary>Gets the kind of case the target's inputs decode to: the invariants that judge it are <see cref="Judges.For"/> of it.</summary>
    public abstract CaseKind Judged { get; }

    /// <summary>
    /// Says why the target cannot fuzz a port: none of the invariants that judge its cases is testable for
    /// it (the ops they need are not offered, or its declared deviations break them by design). Null when at least one
    /// is; the others are skipped on every input, as the gate reports them NOT TESTED.
    /// </summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The reason, or null.</returns>
    public override string? WhyNotFuzzable(ICellPhysics impl)
    {
        ArgumentNullException.ThrowIfNull(impl);
        var judges = Judges.For(Judged);
        if (judges.Any(i => i.IsTestable(impl)))
        {
            return null;
        }

        var needs = judges.Select(i => i.WhyNotTestable(impl)).Distinct().Take(3);
        return $"target {Name}: none of its {judges.Count} invariants is testable for '{impl.Name}' (it offers {string.Join(", ", OpNames.Names(impl.Ops).Concat(Transports.Negotiated(impl)))}): {string.Join("; ", needs)}";
    }

    /// <summary>Gets the invariants of this target that a subject is tested for (the rest are skipped, as in the gate).</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The testable invariant IDs, in judge order.</returns>
    public override IReadOnlyList<string> TestedFor(ICellPhysics impl) => [.. Judges.For(Judged).Where(i => i.IsTestable(impl)).Select(i => i.Id)];

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(string? fault) => CreateTest(Subject.Of(fault));

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(Subject subject)
    {
        ArgumentNullException.ThrowIfNull(subject);
        _ = subject.Shared(); // an unknown fault or an unloadable port is rejected now, not at the first input
        return data =>
        {
            if (Run(subject, PerInput(subject), Decode(data)) is { } violation)
            {
                throw new InvariantViolationException(violation);
            }
        };
    }

    /// <inheritdoc/>
    public override Finding? Classify(byte[] input, string? fault) => Classify(input, Subject.Of(fault));

    /// <inheritdoc/>
    public override Finding? Classify(byte[] input, Subject subject)
    {
        ArgumentNullException.ThrowIfNull(subject);
        var c = Decode(input);
        if (!subject.IsExternal)
        {
            return Check(subject.Fresh(), c) is { } v ? new Finding(v.InvariantId, Signatures.Of(v.Message), v.ToString(), AnyCase.Of(c)) : null;
        }

        try
        {
            return Run(subject, subject.Fresh(), c) is { } v ? new Finding(v.InvariantId, Signatures.Of(v.Message), v.ToString(), AnyCase.Of(c)) : null;
        }
#pragma warning disable CA1031 // A port's crash, hang, garbage answer or exception is a finding of its own kind.
        catch (Exception e) when (e is not OutOfMemoryException)
#pragma warning restore CA1031
        {
            return e is AdapterFailureException
                ? new Finding(AdapterFailureKey, Signatures.Of(e.Message), e.Message, null)
                : new Finding(e.GetType().Name, Signatures.Of(e), e.ToString(), null);
        }
    }

    /// <inheritdoc/>
    public override CorpusEntry? AsEntry(byte[] input, string title, string origin) =>
        CorpusEntry.From(Decode(input), title, null, FinderNames.Fuzz, origin);

    /// <inheritdoc/>
    public override CorpusEntry? Minimise(Finding finding, string? fault, string origin) => Minimise(finding, Subject.Of(fault), origin);

    /// <summary>
    /// Shrinks greedily as FsCheck does (take the first simpler candidate that still fails, start again) while the
    /// same invariant stays broken; for a planted fault or a port the case must also keep holding on the reference, so
    /// the stored file is a regression that tells the subject from the correct core.
    /// </summary>
    /// <param name="finding">A finding of this target.</param>
    /// <param name="subject">The campaign's implementation.</param>
    /// <param name="origin">Where the input came from.</param>
    /// <returns>The entry.</returns>
    public override CorpusEntry? Minimise(Finding finding, Subject subject, string origin)
    {
        ArgumentNullException.ThrowIfNull(finding);
        ArgumentNullException.ThrowIfNull(subject);
        if (finding.Case?.Value is not TCase start)
        {
            return null;
        }

        // Every check gets a fresh implementation, as Classify and acphys replay do: a stateful fault (no-reset keeps
        // the previous query's cells) must not carry one candidate's history into the next, or a case that failed a
        // moment ago can pass when checked again. A child process is one per campaign (its answers carry no state
        // between requests by protocol v1's rules).
        bool separates = subject != Subject.Reference && Check(ReferenceAdapter.Instance, start) is null;
        Violation? FailureOf(TCase c)
        {
            Violation? v;
            try
            {
                v = Run(subject, subject.Fresh(), c);
            }
#pragma warning disable CA1031 // A candidate that crashes a port (or makes it throw) is another finding's, not this one's shrink.
            catch (Exception e) when (subject.IsExternal && e is not OutOfMemoryException)
#pragma warning restore CA1031
            {
                if (e is AdapterFailureException)
                {
                    subject.Discard();
                }

                return null;
            }

            return v is not null && v.InvariantId == finding.Key && (!separates || Check(ReferenceAdapter.Instance, c) is null) ? v : null;
        }

        if (FailureOf(start) is not { } violation)
        {
            return null; // it does not fail the same way on a fresh implementation: kept as a raw input by triage
        }

        bool StillFails(TCase candidate)
        {
            if (FailureOf(candidate) is { } v)
            {
                violation = v;
                return true;
            }

            return false;
        }

        var current = GreedyShrink.Run(start, Shrink, StillFails, ShrinkBudget);

        var entry = CorpusEntry.From(current, $"{violation.InvariantId}: {violation.Message}", violation.InvariantId, FinderNames.Fuzz, origin)
            ?? throw new InvalidOperationException($"{typeof(TCase).Name} has no corpus format");
        return separates && subject.Fault is { } fault ? entry with { Catches = [fault] } : entry;
    }

    /// <summary>The key of a finding where a port could not answer at all (crash, hang past the timeout, an answer that is not protocol v1).</summary>
    public const string AdapterFailureKey = "ADAPTER-FAILURE";

    /// <summary>Gets the implementation one input runs against: the long-lived one, or a fresh one where an input must not see another's state.</summary>
    /// <param name="subject">The subject.</param>
    /// <returns>The implementation.</returns>
    protected virtual ICellPhysics PerInput(Subject subject)
    {
        ArgumentNullException.ThrowIfNull(subject);
        return subject.Shared();
    }

    // One input's check; a child that pipelines streams the input's queries (docs/protocol.md, "Pipelining"); a child
    // that failed is dropped so the next input starts a new one (its failure is this input's finding).
    private Violation? Run(Subject subject, ICellPhysics impl, TCase c)
    {
        if (impl is not ProcessAdapter child)
        {
            return Check(impl, c);
        }

        try
        {
            return child.Pipelines ? child.Pipelined(() => Check(impl, c)) : Check(impl, c);
        }
        catch (AdapterFailureException)
        {
            subject.Discard();
            throw;
        }
    }
}
