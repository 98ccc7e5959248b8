using AcPhys.Spec.Adapters;

namespace AcPhys.Spec.Invariants;

/// <summary>An invariant: a stable ID, one sentence of what it means, the spec section it rests on, and the operations it needs.</summary>
public abstract class Invariant
{
    /// <summary>Initializes a new instance.</summary>
    /// <param name="id">Stable upper-case ID, e.g. <c>LCOORD-ROUNDTRIP</c>.</param>
    /// <param name="statement">One sentence of what it means.</param>
    /// <param name="source">The spec section(s) it implements.</param>
    /// <param name="requires">Operations an implementation must offer for it to be tested.</param>
    protected Invariant(string id, string statement, string source, Op requires)
    {
        Id = id;
        Statement = statement;
        Source = source;
        Requires = requires;
    }

    /// <summary>Gets the stable ID.</summary>
    public string Id { get; }

    /// <summary>Gets the one-sentence statement.</summary>
    public string Statement { get; }

    /// <summary>Gets the spec section(s) it implements.</summary>
    public string Source { get; }

    /// <summary>Gets the operations it needs.</summary>
    public Op Requires { get; }

    /// <summary>Gets the kind of case it checks.</summary>
    public abstract Type CaseType { get; }

    /// <summary>Tests whether an implementation offers everything this invariant needs.</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>True when it can be tested.</returns>
    public bool IsTestable(ICellPhysics impl) => (impl.Ops & Requires) == Requires;

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
    /// <param name="check">The check.</param>
    public Invariant(string id, string statement, string source, Op requires, Func<ICellPhysics, TCase, Outcome> check)
        : base(id, statement, source, requires) => this.check = check;

    /// <inheritdoc/>
    public override Type CaseType => typeof(TCase);

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
