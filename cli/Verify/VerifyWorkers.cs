using AcPhys.Contract;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>
/// The threads a <c>verify</c> run spreads its invariants over (<c>--jobs</c>, issue 51): the bundled reference on every
/// processor, sharing its one instance (stateless: its scratch array is per thread); a planted fault one instance per
/// thread in the same declared mode, or one thread for a fault that carries state from call to call
/// (<see cref="StatefulFaults"/>); an implementation of a port (<c>--impl</c>, <c>--impl-cmd</c>) always one thread,
/// since its code need not be thread-safe and a race read as a violation would be a false alarm.
/// </summary>
internal static class VerifyWorkers
{
    /// <summary>Returns the workers of a run.</summary>
    /// <param name="settings">The run's settings (<see cref="VerifySettings.Jobs"/> null: one per processor).</param>
    /// <param name="impl">The implementation the run's own thread asks.</param>
    /// <returns>The workers.</returns>
    public static CatalogueWorkers For(VerifySettings settings, ICellPhysics impl)
    {
        int jobs = settings.Jobs ?? CatalogueWorkers.Auto;
        if (settings.Implementation.IsExternal || jobs <= 1)
        {
            return CatalogueWorkers.One;
        }

        if (settings.Fault is not { } fault)
        {
            return impl is ReferenceAdapter ? new CatalogueWorkers(jobs, () => impl) : CatalogueWorkers.One;
        }

        return StatefulFaults.All.Contains(fault)
            ? CatalogueWorkers.One
            : new CatalogueWorkers(jobs, () => Impl.ReferenceChoice.Declared(PlantedFaults.Create(fault.Id), settings.Pick, settings.Fidelity));
    }
}
