namespace AcPhys.Spec.Faults;

/// <summary>
/// The planted faults whose answers depend on the calls before them: their arrays are never cleared (facts §7 #6, ACE's
/// find_cell_list keeps its dictionary), so an invariant's first answers carry the last calls of the invariant before it.
/// A catalogue run that spread them over several instances would change those answers (issue 51): they run on one
/// thread. Every other fault keeps only scratch state per instance, reset on each call, and runs one instance per thread.
/// </summary>
internal static class StatefulFaults
{
    /// <summary>Gets the faults that carry state from call to call.</summary>
    public static IReadOnlyList<PlantedFault> All { get; } = [PlantedFaults.NoReset, IndoorFaults.StaleSceneArray];
}
