using AcPhys.Spec.Faults;

namespace AcPhys.Spec.Judging;

/// <summary>Whether a case catches one planted fault a file lists in <c>catches</c>.</summary>
/// <param name="Id">The fault id as the file spells it.</param>
/// <param name="Fault">The fault, or null when no planted fault has that id.</param>
/// <param name="CaughtBy">The invariants the case violates with the fault switched on (empty: not caught).</param>
public sealed record FaultCatch(string Id, PlantedFault? Fault, IReadOnlyList<string> CaughtBy);
