namespace AcPhys.Spec.Faults;

/// <summary>A named, deliberately injected defect that the suite must catch: proof that the invariants bite.</summary>
/// <param name="Id">Stable lower-case id, e.g. <c>trunc-floor</c>; used by <c>--fault</c> and <c>ACPHYS_FAULT</c>.</param>
/// <param name="Title">One line.</param>
/// <param name="Story">Where the bug comes from.</param>
/// <param name="CaughtBy">Invariant IDs expected to catch it.</param>
public sealed record PlantedFault(string Id, string Title, string Story, IReadOnlyList<string> CaughtBy);
