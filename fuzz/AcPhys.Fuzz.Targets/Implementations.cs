using AcPhys.Spec.Adapters;
using AcPhys.Spec.Faults;

namespace AcPhys.Fuzz.Targets;

/// <summary>The implementation a campaign runs against.</summary>
public static class Implementations
{
    /// <summary>Returns the reference, or the reference with a planted fault switched on.</summary>
    /// <param name="fault">The fault id, or null.</param>
    /// <returns>The implementation.</returns>
    /// <exception cref="ArgumentException">Unknown fault.</exception>
    public static ICellPhysics For(string? fault) => fault is null ? ReferenceAdapter.Instance : PlantedFaults.Create(fault);
}
