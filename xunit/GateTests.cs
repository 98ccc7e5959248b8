using AcPhys.Contract;
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
        var verdict = GateSubject<TAdapter>.Verdict(invariant);
        Skip.If(verdict.NotTested is not null, verdict.NotTested);
        if (verdict.Failure is string failure)
        {
            throw new GateFailure(failure);
        }
    }

    /// <summary>
    /// Gets the fewest invariants this port's gate must test to pass (default 1: a run that tests nothing never passes);
    /// override it with the count the port reaches today, so that an operation it stops announcing fails the gate.
    /// <c>ACPHYS_MIN_TESTED</c>, when set, wins (as <c>acphys verify --min-tested</c> on the command line).
    /// </summary>
    protected virtual int MinTested => 1;

    /// <summary>
    /// Fails unless at least <see cref="MinTested"/> invariants are tested (neither NOT TESTED by the announced operations
    /// nor left unjudged by every case): <c>acphys verify --min-tested</c>'s exit 4, with its wording.
    /// </summary>
    [Fact]
    public void TestsAtLeastMinTested()
    {
        var impl = GateSubject<TAdapter>.Adapter;
        int? set = GateFloor.FromEnvironment();
        int floor = set ?? MinTested;
        string source = set is null ? $"{GetType().Name}.{nameof(MinTested)}" : GateFloor.Variable;
        var all = InvariantCatalogue.All;

        // Statically NOT TESTED rows (the ops) first, so a port far under the floor fails without running anything.
        var candidates = all.Where(i => i.WhyNotTestable(impl) is null).ToList();
        var tested = candidates.Count >= floor ? candidates.Where(i => GateSubject<TAdapter>.Verdict(i.Id).NotTested is null).ToList() : candidates;
        if (tested.Count < floor)
        {
            var skipped = all.Except(tested).Select(i => i.Id).ToList();
            throw new GateFailure(
                $"not a pass: {tested.Count} of {all.Count} invariants tested, fewer than the floor {floor} ({source}); {impl.Name} announces " +
                $"{string.Join(", ", OpNames.Names(impl.Ops))}; not tested: {string.Join(", ", skipped.Take(12))}{(skipped.Count > 12 ? $" and {skipped.Count - 12} more" : string.Empty)} " +
                "(docs/ports.md, \"Announce only what you have\")");
        }
    }
}
