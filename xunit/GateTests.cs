using AcPhys.Spec.Adapters;
using AcPhys.Spec.Invariants;
using Xunit;

namespace AcPhys.Xunit;

/// <summary>
/// The PR gate as tests in a port's own xunit project: derive a sealed class, e.g.
/// <c>public sealed class MyPortGate : GateTests&lt;MyAdapter&gt; { }</c>, and <c>dotnet test</c> runs one test per
/// invariant of the catalogue, named by its ID, against <typeparamref name="TAdapter"/> — the verdicts of
/// <c>acphys verify --impl</c> on the same adapter.
/// </summary>
/// <remarks>
/// A failing test's message is the finding as <c>acphys verify</c> prints it (statement, shrunk case, message, seed,
/// replay line, case file); an invariant the adapter cannot be judged on is skipped with the reason verify prints after
/// NOT TESTED. <c>ACPHYS_PROFILE</c> (pr, nightly) chooses the budget and <c>ACPHYS_SEED</c> replays one seed, as in
/// props; case files go to <c>ACPHYS_FAILURES</c>, else artifacts/failures under the working folder.
/// </remarks>
/// <typeparam name="TAdapter">The port's adapter: a public class with a parameterless constructor.</typeparam>
public abstract class GateTests<TAdapter>
    where TAdapter : ICellPhysics, new()
{
    /// <summary>Gets every invariant ID of the catalogue, one theory row each.</summary>
    public static TheoryData<string> Invariants { get; } = new(InvariantCatalogue.All.Select(i => i.Id));

    /// <summary>Checks one invariant of the catalogue against the adapter under the profile's budget.</summary>
    /// <param name="invariant">The invariant ID.</param>
    [SkippableTheory]
    [MemberData(nameof(Invariants))]
    public void Holds(string invariant)
    {
        var verdict = Gate.Check(GateSubject<TAdapter>.Adapter, invariant);
        Skip.If(verdict.NotTested is not null, verdict.NotTested);
        if (verdict.Failure is string failure)
        {
            throw new GateFailure(failure);
        }
    }

    /// <summary>A run that could test nothing never passes (<c>acphys verify</c>'s exit 4): the adapter offers an operation some invariant needs.</summary>
    [Fact]
    public void OffersSomethingToTest()
    {
        var impl = GateSubject<TAdapter>.Adapter;
        if (!InvariantCatalogue.All.Any(i => i.WhyNotTestable(impl) is null))
        {
            throw new GateFailure($"not a pass: {impl.Name} announces {string.Join(", ", OpNames.Names(impl.Ops))}, which no invariant can be tested on (docs/ports.md, \"Announce only what you have\")");
        }
    }
}
