using AcPhys.Contract;
using AcPhys.Spec.Cases;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Diff;

/// <summary>
/// One differential check of <c>acphys diff</c>: a stable ID, one sentence, the ops it compares, and a comparison
/// that names the divergence class of an input (or null when both sides answer alike).
/// </summary>
/// <param name="Id">Stable ID, e.g. <c>DIFF-WALK</c>.</param>
/// <param name="Statement">One sentence of what it compares.</param>
/// <param name="Requires">Ops the implementation must offer (<see cref="Op.None"/>: any of the LandDefs ops).</param>
internal abstract record DiffCheck(string Id, string Statement, Op Requires)
{
    /// <summary>Says why an implementation cannot be compared, or null when it can.</summary>
    /// <param name="impl">The implementation.</param>
    /// <returns>The reason, or null.</returns>
    public string? WhyNotCompared(ICellPhysics impl) =>
        Requires == Op.None
            ? (impl.Ops & Op.LandDefs) == Op.None ? "implementation offers no LandDefs op" : null
            : (impl.Ops & Requires) != Requires ? "implementation lacks " + string.Join(", ", OpNames.Names(Requires & ~impl.Ops)) : null;

    /// <summary>Runs the check over every generated input.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="cases">How many inputs to generate.</param>
    /// <param name="seed">The seed.</param>
    /// <returns>The result.</returns>
    public abstract DiffResult Run(ICellPhysics impl, int cases, Seed seed);
}

/// <summary>A differential check over inputs of type <typeparamref name="TCase"/>.</summary>
/// <typeparam name="TCase">The input type.</typeparam>
/// <param name="Id">Stable ID.</param>
/// <param name="Statement">One sentence.</param>
/// <param name="Requires">Ops compared.</param>
/// <param name="Domain">Where inputs come from, how they shrink, and their boundary classes.</param>
/// <param name="Compare">Names the divergence of an input, or null when both sides agree.</param>
internal sealed record DiffCheck<TCase>(string Id, string Statement, Op Requires, ICaseDomain<TCase> Domain, Func<ICellPhysics, TCase, Divergence?> Compare)
    : DiffCheck(Id, Statement, Requires)
{
    /// <inheritdoc/>
    public override DiffResult Run(ICellPhysics impl, int cases, Seed seed) => DiffRunner.Run(this, impl, cases, seed);
}
