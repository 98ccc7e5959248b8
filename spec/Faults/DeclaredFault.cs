using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// A planted fault served under a declaration (issue 41, "the intended line is proved"): every answer is the faulty
/// port's, only the declared pick and deviations change — what a maintainer does who follows advice to declare a
/// deviation without changing the code. A declaration must never turn a real bug green, so the gate still fails it
/// (<c>verify --fault F --fidelity X</c>, <c>serve --fault F --fidelity X</c>).
/// </summary>
public static class DeclaredFault
{
    /// <summary>Returns a planted fault declaring a mode.</summary>
    /// <param name="faultId">The planted fault.</param>
    /// <param name="pick">The declared pick; null keeps the fault's own.</param>
    /// <param name="indoor">The declared indoor deviations; null keeps the fault's own.</param>
    /// <param name="outdoor">The declared outdoor deviations; null keeps the fault's own.</param>
    /// <returns>The faulty implementation, declaring that mode.</returns>
    public static ICellPhysics Create(string faultId, PickPolicy? pick, IndoorFidelity? indoor, OutdoorFidelity? outdoor) =>
        Declaring(PlantedFaults.Create(faultId), pick, indoor, outdoor);

    /// <summary>Returns an implementation's answers under another declaration.</summary>
    /// <param name="impl">The implementation.</param>
    /// <param name="pick">The declared pick; null keeps its own.</param>
    /// <param name="indoor">The declared indoor deviations; null keeps its own.</param>
    /// <param name="outdoor">The declared outdoor deviations; null keeps its own.</param>
    /// <returns>The implementation itself when nothing changes, else a wrapper declaring the mode.</returns>
    public static ICellPhysics Declaring(ICellPhysics impl, PickPolicy? pick, IndoorFidelity? indoor, OutdoorFidelity? outdoor) =>
        pick is null && indoor is null && outdoor is null
            ? impl
            : new OpsOffered(impl, impl.Ops) { Pick = pick ?? impl.Pick, Indoor = indoor ?? impl.Indoor, Outdoor = outdoor ?? impl.Outdoor };
}
