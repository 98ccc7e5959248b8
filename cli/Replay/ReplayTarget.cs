using AcPhys.Contract;
using AcPhys.Spec.Faults;

namespace AcPhys.Cli.Replay;

/// <summary>What a replayed file is checked against: the reference core, or the reference with a planted fault.</summary>
/// <param name="Impl">The implementation.</param>
/// <param name="Fault">The planted fault switched on, if any.</param>
internal sealed record ReplayTarget(ICellPhysics Impl, PlantedFault? Fault);
