using AcPhys.Contract;
using AcPhys.Spec.Corpus;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;
using Xunit.Abstractions;
using Xunit.Sdk;

namespace AcPhys.Props.Support;

/// <summary>
/// The catalogue bridge: runs an invariant of the catalogue (spec's <see cref="Invariant.Run"/>) with the CI seed,
/// writes the invariant's class distribution to the test output, and on failure throws with the seed, a failure file
/// and the replay commands.
/// </summary>
/// <remarks>
/// <para>
/// Every property that is a plain FsCheck property is an FsCheck.Xunit test (<see cref="CiPropertyAttribute"/> for the
/// profile's seed, <c>FixedSeedPropertyAttribute</c> for the mutation-killing ones), failing with FsCheck's own
/// <c>Replay</c>. This bridge is kept only for what FsCheck.Xunit cannot do for the catalogue: one
/// <c>ACPHYS_SEED</c> replaying every invariant at once, each invariant's seed derived from the profile's base seed
/// and its ID, the profiles' case counts (5,000 in pr, 200,000 in nightly), failure files in artifacts/failures, the
/// <c>acphys replay</c> and <c>acphys verify --only</c> lines printed on failure, and tests that expect an invariant to
/// fail (planted faults and known bugs are caught).
/// </para>
/// <para>
/// Environment: <c>ACPHYS_PROFILE=nightly</c> (fresh seeds, 40× the cases), <c>ACPHYS_SEED=seed,gamma[,size]</c>
/// (replay one seed for every property).
/// </para>
/// </remarks>
internal static class PropertyRun
{
    /// <summary>Gets the profile chosen by <c>ACPHYS_PROFILE</c> (default pr).</summary>
    public static Profile Profile { get; } = ToolEnvironment.Process.Profile ?? Profile.Pr;

    private static readonly ulong RunBase = Profile.BaseSeed ?? Seed.Fresh().Value;

    /// <summary>Runs an invariant against an implementation and fails the test on a violation.</summary>
    /// <param name="invariant">The invariant.</param>
    /// <param name="output">xunit output.</param>
    /// <param name="impl">The implementation (the reference when null).</param>
    /// <returns>The result, for further assertions.</returns>
    public static InvariantResult Check(Invariant invariant, ITestOutputHelper output, ICellPhysics? impl = null)
    {
        impl ??= ReferenceAdapter.Instance;
        var seed = SeedFor(invariant.Id);
        output.WriteLine($"{invariant.Id}: {invariant.Statement}");
        output.WriteLine($"profile {Profile.Name}, seed {seed}");
        var result = invariant.Run(impl, Profile.CasesPerInvariant, seed, output.WriteLine);
        output.WriteLine($"cases {result.Cases}, applicable {result.Applicable}, {result.Elapsed.TotalMilliseconds:F0} ms");
        output.WriteLine("classes: " + string.Join(", ", result.Classes.OrderBy(k => k.Key).Select(k => $"{k.Key}={k.Value}")));
        if (result.Status == ResultStatus.Failed)
        {
            throw new XunitException(FailureText(result, impl));
        }

        Assert.Equal(ResultStatus.Passed, result.Status);
        return result;
    }

    /// <summary>Returns the seed for a property: <c>ACPHYS_SEED</c> when set, else derived from the profile's base seed.</summary>
    /// <param name="invariantId">The invariant ID.</param>
    /// <returns>The seed.</returns>
    public static Seed SeedFor(string invariantId)
    {
        var settings = ToolEnvironment.Process;
        return settings.Problem(ToolEnvironment.SeedVariable) is { } problem ? throw new XunitException(problem)
            : settings.Seed ?? Seed.Derive(RunBase, invariantId);
    }

    /// <summary>Formats a failure: invariant, shrunk and original case, seed, and the replay commands.</summary>
    /// <param name="result">The failed result.</param>
    /// <param name="impl">The implementation.</param>
    /// <returns>The text.</returns>
    public static string FailureText(InvariantResult result, ICellPhysics impl)
    {
        var replay = result.Replay ?? result.Seed;
        string fault = impl.Name.StartsWith("reference+", StringComparison.Ordinal) ? " --fault " + impl.Name["reference+".Length..] : string.Empty;
        string file = result.Violation is { } v
            && FailureFile.Write(v, Path.Combine(RepoPaths.Root, "artifacts", "failures"), "props", result.Seed.ToString()) is string path
            ? path
            : "(this case type is not stored)";
        return string.Join(
            Environment.NewLine,
            $"  case file: {file}",
            $"  replay:   ./acphys replay {Path.GetRelativePath(RepoPaths.Root, file)}{fault}",
            $"{result.Invariant.Id} violated by {impl.Name}: {result.Invariant.Statement}",
            $"  shrunk:   {result.Violation}",
            $"  original: {result.Original}",
            $"  seed:     {result.Seed} (profile {Profile.Name})",
            $"  replay:   ./acphys verify --only {result.Invariant.Id} --seed {replay}{fault}",
            $"  or:       ACPHYS_SEED={result.Seed} dotnet test props -c Release --filter \"DisplayName~{result.Invariant.Id}\"");
    }
}
