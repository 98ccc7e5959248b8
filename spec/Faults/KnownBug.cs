namespace AcPhys.Spec.Faults;

/// <summary>
/// One entry of the known-bug catalogue (mutation/known-bugs/*.json, docs/bite.md): a bug this field has actually
/// had, the planted fault that switches it on in the reference, and the invariants expected to catch it.
/// </summary>
/// <param name="Id">Stable lower-case id; also the file name (without <c>.json</c>).</param>
/// <param name="Title">One line.</param>
/// <param name="Story">What went wrong and what it breaks.</param>
/// <param name="Source">Where it comes from: facts sections, the seed, ACE or retail citations, issues.</param>
/// <param name="Fault">The id of the planted fault (spec/Faults) that switches it on.</param>
/// <param name="CaughtBy">Invariant IDs expected to catch it (each must catch it under the pr profile).</param>
/// <param name="PendingOn">The branch whose fault, scenes or invariants this entry waits for, or null when it is wired. A
/// pending entry whose fault exists is one no invariant catches on today's scenes (its fault's CaughtBy is empty).</param>
public sealed record KnownBug(string Id, string Title, string Story, string Source, string Fault, IReadOnlyList<string> CaughtBy, string? PendingOn)
{
    /// <summary>Gets the planted fault that switches the bug on, or null when it is not available (yet).</summary>
    public PlantedFault? PlantedFault => PlantedFaults.Find(Fault);

    /// <summary>Gets a value indicating whether the fault exists and the entry is wired, so the bug can be run.</summary>
    public bool IsAvailable => PlantedFault is not null && PendingOn is null;

    /// <summary>Gets why the bug cannot be run, or null when it can.</summary>
    public string? NotAvailableReason => IsAvailable ? null
        : PendingOn is not null && PlantedFault is not null ? $"fault not caught yet: '{Fault}' exists but today's scenes cannot reach it; it waits for branch '{PendingOn}'"
        : PendingOn is not null ? $"fault not available yet: '{Fault}' is being built on branch '{PendingOn}'"
        : $"fault '{Fault}' does not exist (see: acphys faults)";
}
