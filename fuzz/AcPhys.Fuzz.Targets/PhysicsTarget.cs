using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Invariants;

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

    /// <summary>Returns simpler candidates (the properties' shrinker).</summary>
    /// <param name="c">The case.</param>
    /// <returns>Candidates.</returns>
    public abstract IEnumerable<TCase> Shrink(TCase c);

    /// <inheritdoc/>
    public override Action<ReadOnlySpan<byte>> CreateTest(string? fault)
    {
        var impl = Implementations.For(fault);
        return data =>
        {
            if (Check(impl, Decode(data)) is { } violation)
            {
                throw new InvariantViolationException(violation);
            }
        };
    }

    /// <inheritdoc/>
    public override Finding? Classify(byte[] input, string? fault)
    {
        var c = Decode(input);
        return Check(Implementations.For(fault), c) is { } v ? new Finding(v.InvariantId, Signatures.Of(v.Message), v.ToString(), AnyCase.Of(c)) : null;
    }

    /// <summary>
    /// Shrinks greedily as FsCheck does (take the first simpler candidate that still fails, start again) while the
    /// same invariant stays broken; under a planted fault the case must also keep holding on the reference, so the
    /// stored file is a regression that tells the fault from the correct core.
    /// </summary>
    /// <param name="finding">A finding of this target.</param>
    /// <param name="fault">The campaign's fault, or null.</param>
    /// <param name="origin">Where the input came from.</param>
    /// <returns>The entry.</returns>
    public override CorpusEntry? Minimise(Finding finding, string? fault, string origin)
    {
        ArgumentNullException.ThrowIfNull(finding);
        if (finding.Case?.Value is not TCase start)
        {
            return null;
        }

        // Every check gets a fresh implementation, as Classify and acphys replay do: a stateful fault (no-reset keeps
        // the previous query's cells) must not carry one candidate's history into the next, or a case that failed a
        // moment ago can pass when checked again.
        bool separates = fault is not null && Check(ReferenceAdapter.Instance, start) is null;
        Violation? FailureOf(TCase c) =>
            Check(Implementations.For(fault), c) is { } v && v.InvariantId == finding.Key && (!separates || Check(ReferenceAdapter.Instance, c) is null) ? v : null;

        if (FailureOf(start) is not { } violation)
        {
            return null; // it does not fail the same way on a fresh implementation: kept as a raw input by triage
        }

        var current = start;
        int budget = ShrinkBudget;
        bool progressed = true;
        while (progressed && budget > 0)
        {
            progressed = false;
            foreach (var candidate in Shrink(current))
            {
                if (--budget < 0)
                {
                    break;
                }

                if (FailureOf(candidate) is { } v)
                {
                    (current, violation) = (candidate, v);
                    progressed = true;
                    break;
                }
            }
        }

        var entry = CorpusEntry.From(current, $"{violation.InvariantId}: {violation.Message}", violation.InvariantId, FinderNames.Fuzz, origin)
            ?? throw new InvalidOperationException($"{typeof(TCase).Name} has no corpus format");
        return separates ? entry with { Catches = [fault!] } : entry;
    }
}
