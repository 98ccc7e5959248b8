using AcPhys.Contract;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Values;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Xunit;

/// <summary>
/// Runs one invariant of the catalogue as <c>acphys verify --impl</c> does (<see cref="CatalogueRunner.RunInvariant"/>:
/// the same seeds, cases and exhaustive sweeps) and words the verdict as verify prints it.
/// </summary>
public static class Gate
{
    /// <summary>Gets the profile chosen by <c>ACPHYS_PROFILE</c> (pr when unset).</summary>
    public static Profile Profile { get; } = ProfileFrom(ToolEnvironment.Process);

    // A profile without a fixed base seed (nightly) draws one per test run: every failure prints the seed that replays it.
    private static readonly ulong RunBase = Profile.BaseSeed ?? Seed.Fresh().Value;

    /// <summary>Gets the seed <c>ACPHYS_SEED</c> fixes for every invariant, or null.</summary>
    public static Seed? FixedSeed { get; } = SeedFrom(ToolEnvironment.Process);

    /// <summary>Checks one invariant against an adapter.</summary>
    /// <param name="impl">The adapter.</param>
    /// <param name="invariantId">The invariant ID.</param>
    /// <returns>The verdict.</returns>
    /// <exception cref="ArgumentException">No invariant has that ID.</exception>
    /// <exception cref="AdapterFailureException">The adapter could not answer at all (verify's exit 2).</exception>
    public static GateVerdict Check(ICellPhysics impl, string invariantId)
    {
        var invariant = InvariantCatalogue.Find(invariantId) ?? throw new ArgumentException($"no invariant '{invariantId}' (see: acphys invariants)", nameof(invariantId));
        var result = CatalogueRunner.RunInvariant(invariant, impl, Profile, RunBase, FixedSeed);
        return result.Status switch
        {
            ResultStatus.NotTested => new GateVerdict(result.NotTestedReason ?? "the implementation lacks an operation it needs", null),
            ResultStatus.Failed => new GateVerdict(null, FailureText(result, impl)),
            _ => new GateVerdict(null, null),
        };
    }

    /// <summary>Gets the folder shrunk failing cases are written to: <c>ACPHYS_FAILURES</c>, else artifacts/failures.</summary>
    public static string FailureFolder => ToolEnvironment.Process.FailureFolder ?? Path.Combine("artifacts", "failures");

    private static string FailureText(InvariantResult result, ICellPhysics impl)
    {
        string program = ToolEnvironment.Process.Command;
        var replay = new ReplayCommand(program, Profile) { Implementation = ["--impl", impl.GetType().Assembly.Location] };
        string name = InputQuote.Line(impl.Name ?? impl.GetType().Name, 120);
        var block = FailureBlock.Of(result, impl, name, replay, FailureFolder, FinderNames.Verify);
        // The same failure from this test project: the invariant's whole generated run again under its seed (deterministic),
        // or, for a sweep's finding, the profile's run (a fixed seed sweeps nothing).
        bool swept = result.Replay is null && result.ExhaustiveCases > 0;
        string env = (Profile.Name == "pr" ? string.Empty : $"ACPHYS_PROFILE={Profile.Name} ") + (swept ? string.Empty : $"ACPHYS_SEED={result.Seed} ");
        return block.Text + Environment.NewLine + $"  {"or",-10} {env}dotnet test --filter \"DisplayName~{result.Invariant.Id}\"";
    }

    private static Profile ProfileFrom(ToolEnvironment settings) =>
        settings.Problem(ToolEnvironment.ProfileVariable) is { } problem ? throw new InvalidOperationException(problem) : settings.Profile ?? Profile.Pr;

    private static Seed? SeedFrom(ToolEnvironment settings) =>
        settings.Problem(ToolEnvironment.SeedVariable) is { } problem ? throw new InvalidOperationException(problem) : settings.Seed;
}
