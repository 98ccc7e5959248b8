using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Judging;
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
    /// <param name="sceneForms">The scene query kinds it is stated for (<see cref="SceneForms"/>), or none.</param>
    protected Invariant(string id, string statement, string source, Op requires, PickPolicy? requiresPick, Op sceneForms = Op.None)
    {
        Id = id;
        Statement = statement;
        Source = source;
        Requires = requires;
        RequiresPick = requiresPick;
        SceneForms = sceneForms & (SceneQueryKinds.Either | PartsIndoorInvariants.Either);
    }

    /// <summary>Gets the stable ID.</summary>
    public string Id { get; }

    /// <summary>Gets the one-sentence statement.</summary>
    public string Statement { get; }

    /// <summary>Gets the spec section(s) it implements.</summary>
    public string Source { get; }

    /// <summary>Gets the operations it needs, besides a scene query (<see cref="SceneForms"/>).</summary>
    public Op Requires { get; }

    /// <summary>
    /// Gets the scene query kinds the invariant is stated for: <see cref="Op.FindCellScene"/> (static placement),
    /// <see cref="Op.FindCellTransition"/>, or both; an implementation offering any of them is tested in the kinds it
    /// offers (<see cref="SceneQueryKinds"/>). <see cref="Op.None"/> for an invariant that asks no scene query.
    /// </summary>
    public Op SceneForms { get; }

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

    /// <summary>
    /// Says why an implementation cannot be tested against this invariant, or null when it can: an operation or the
    /// pick it lacks, or a deviation it declares that breaks this statement by design (<see cref="BrokenByDesign"/>).
    /// </summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The reason, or null.</returns>
    public string? WhyNotTestable(ICellPhysics impl) =>
        WhyNotTestable(impl.Ops, impl.Pick) ?? BrokenByDesign.WhyNotJudged(Id, impl.Indoor, impl.Outdoor);

    /// <summary>Says why an implementation offering these operations and declaring this pick cannot be tested, or null when it can.</summary>
    /// <param name="ops">The operations it offers.</param>
    /// <param name="pick">The pick it declares.</param>
    /// <returns>The reason, or null.</returns>
    public string? WhyNotTestable(Op ops, PickPolicy pick)
    {
        if ((ops & Requires) != Requires)
        {
            return "implementation lacks " + string.Join(", ", OpNames.Names(Requires & ~ops));
        }

        if (SceneForms != Op.None && (ops & SceneForms) == 0)
        {
            // A scene invariant stated for one kind only, and the implementation offers the other (issue #29).
            return SceneQueryKinds.OffersScenes(ops) && (SceneForms & PartsIndoorInvariants.Either) == 0
                ? $"states {(SceneForms == Op.FindCellScene ? "static placement" : "the movement transition")} only ({OpNames.Names(SceneForms)[0]}); implementation offers {string.Join(", ", OpNames.Names(ops & SceneQueryKinds.Either))}"
                : "implementation lacks " + string.Join(" or ", OpNames.Names(SceneForms));
        }

        return RequiresPick is PickPolicy p && pick != p
            ? $"applies to the {PickNames.Of(p)} pick; implementation declares {PickNames.Of(pick)}"
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
    /// <param name="sceneForms">The scene query kinds it is stated for, or none (<see cref="Invariant.SceneForms"/>).</param>
    public Invariant(string id, string statement, string source, Op requires, ICaseDomain<TCase> domain, Func<ICellPhysics, TCase, Outcome> check, PickPolicy? requiresPick = null, Op sceneForms = Op.None)
        : base(id, statement, source, requires, requiresPick, sceneForms)
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
    /// every input), except <see cref="AdapterFailureException"/>, which is a tool error and propagates, and
    /// <see cref="UnposableQueryException"/>, a case the tool could not ask exactly (not judged).
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
        catch (UnposableQueryException e)
        {
            return Outcome.VacuousBecause(e.Message); // the tool could not ask it exactly: not judged (docs/protocol.md, "World frame")
        }
        catch (Exception e)
        {
            return Outcome.Violated($"threw {e.GetType().Name}: {e.Message}");
        }
    }
}
