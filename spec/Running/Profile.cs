namespace AcPhys.Spec.Running;

/// <summary>A verification budget: how many generated cases each invariant gets and where seeds come from.</summary>
/// <param name="Name">Profile name (<c>pr</c>, <c>nightly</c>).</param>
/// <param name="CasesPerInvariant">Generated cases per invariant.</param>
/// <param name="BaseSeed">Fixed base seed, or null for a fresh seed per run (printed, so any run can be replayed).</param>
/// <param name="Exhaustive">Whether the finite domains (every lcoord, every block × 64 cells) are swept too.</param>
public sealed record Profile(string Name, int CasesPerInvariant, ulong? BaseSeed, bool Exhaustive)
{
    /// <summary>Gets the PR gate: fast and deterministic, fixed seeds.</summary>
    public static Profile Pr { get; } = new("pr", 5_000, 0xAC5EED0001UL, true);

    /// <summary>Gets the nightly profile: 40× the cases, fresh seeds.</summary>
    public static Profile Nightly { get; } = new("nightly", 200_000, null, true);

    /// <summary>Gets the mutation-testing profile: fixed seeds, fewer cases, no sweeps, so a mutant run stays short and a kill is never luck.</summary>
    public static Profile Mutation { get; } = new("mutation", 1_000, 0xAC5EED0001UL, false);

    /// <summary>Gets a profile by name.</summary>
    /// <param name="name">pr or nightly.</param>
    /// <returns>The profile, or null.</returns>
    public static Profile? Find(string name) => name.ToLowerInvariant() switch
    {
        "pr" => Pr,
        "nightly" => Nightly,
        "mutation" => Mutation,
        _ => null,
    };
}
