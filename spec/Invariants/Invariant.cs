using AcPhys.Core;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Running;

namespace AcPhys.Spec.Invariants;

/// <summary>An invariant: a stable ID, one sentence of what it means, the spec section it rests on, and the operations it needs.</summary>
public abstract class Invariant
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="id">Stable upper-case ID, e.g. <c>LCOORD-ROUNDTRIP</c>.</param>
    /// <param name="statement">One sentence of what it means.</param>
    /// <param name="source">The spec section(s) it implements.</param>
    /// <param name="requires">Operations an implementation must offer for it to be tested.</param>
    /// <param name="requiresPick">The pick policy the invariant is about, or null for any.</param>
    protected Invariant(string id, string statement, string source, Op requires, PickPolicy? requiresPick)
    {
        Id = id;
        Statement = statement;
        Source = source;
        Requires = requires;
        RequiresPick = requiresPick;
    }

    /// <summary>Gets the stable ID.</summary>
    public string Id { get; }

    /// <summary>Gets the one-sentence statement.</summary>
    public string Statement { get; }

    /// <summary>Gets the spec section(s) it implements.</summary>
    public string Source { get; }

    /// <summary>Gets the operations it needs.</summary>
    public Op Requires { get; }

    /// <summary>Gets the pick policy the invariant is about (STABLE-PICK: retail; HYSTERESIS: current-first), or null.</summary>
    public PickPolicy? RequiresPick { get; }

    /// <summary>Gets the retail / hardening label (<see cref="InvariantScope"/>), or null when the invariant has none.</summary>
    public Scope? Scope => InvariantScope.Of(Id)?.Scope;

    /// <summary>Gets the facts section (retail) or the reason (hardening) of the label, or null.</summary>
    public string? ScopeReason => InvariantScope.Of(Id)?.Reason;

    /// <summary>Gets the kind of case it checks.</summary>
    public abstract Type CaseType { get; }

    /// <summary>Tests whether an implementation offers everything this invariant needs.</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>True when it can be tested.</returns>
    public bool IsTestable(ICellPhysics impl) => WhyNotTestable(impl) is null;

    /// <summary>Says why an implementation cannot be tested against this invariant, or null when it can.</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The reason, or null.</returns>
    public string? WhyNotTestable(ICellPhysics impl)
    {
        if ((impl.Ops & Requires) != Requires)
        {
            return "implementation lacks " + string.Join(", ", OpNames.Names(Requires & ~impl.Ops));
        }

        return RequiresPick is PickPolicy p && impl.Pick != p
            ? $"applies to the {PickNames.Of(p)} pick; implementation declares {PickNames.Of(impl.Pick)}"
            : null;
    }

    /// <summary>Runs this invariant as an FsCheck property over its case domain.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="cases">Generated cases.</param>
    /// <param name="seed">The seed.</param>
    /// <param name="sink">Optional sink for FsCheck's text.</param>
    /// <param name="maxClasses">How many failure classes to search for (1: stop at the first failure, for callers that only need caught or not).</param>
    /// <returns>The result.</returns>
    public abstract InvariantResult Run(ICellPhysics impl, int cases, Seed seed, Action<string>? sink = null, int maxClasses = CatalogueRunner.MaxClasses);

    /// <inheritdoc/>
    public override string ToString() => $"{Id}: {Statement}";
}

/// <summary>An invariant over cases of type <typeparamref name="TCase"/>, with its executable check.</summary>
/// <typeparam name="TCase">The case type.</typeparam>
public sealed class Invariant<TCase> : Invariant
{
    private readonly Func<ICellPhysics, TCase, Outcome> check;

    /// <summary>Initializes a new instance.</summary>
    /// <param name="id">Stable ID.</param>
    /// <param name="statement">One sentence.</param>
    /// <param name="source">Spec section(s).</param>
    /// <param name="requires">Operations needed.</param>
    /// <param name="domain">Where its cases come from.</param>
    /// <param name="check">The check.</param>
    /// <param name="requiresPick">The pick policy it is about, or null.</param>
    public Invariant(string id, string statement, string source, Op requires, ICaseDomain<TCase> domain, Func<ICellPhysics, TCase, Outcome> check, PickPolicy? requiresPick = null)
        : base(id, statement, source, requires, requiresPick)
    {
        this.check = check;
        Domain = domain;
    }

    /// <summary>Gets the case domain.</summary>
    public ICaseDomain<TCase> Domain { get; }

    /// <inheritdoc/>
    public override Type CaseType => typeof(TCase);

    /// <inheritdoc/>
    public override InvariantResult Run(ICellPhysics impl, int cases, Seed seed, Action<string>? sink = null, int maxClasses = CatalogueRunner.MaxClasses) =>
        CatalogueRunner.Run(this, impl, cases, seed, sink, maxClasses);

    /// <summary>
    /// Checks one case. An exception from the implementation is itself a violation (every operation must answer
    /// every input), except <see cref="AdapterFailureException"/>, which is a tool error and propagates.
    /// </summary>
    /// <param name="impl">The implementation under test.</param>
    /// <param name="c">The case.</param>
    /// <returns>The outcome.</returns>
    public Outcome Check(ICellPhysics impl, TCase c)
    {
        try
        {
            return check(impl, c);
        }
        catch (AdapterFailureException)
        {
            throw;
        }
        catch (Exception e)
        {
            return Outcome.Violated($"threw {e.GetType().Name}: {e.Message}");
        }
    }
}
