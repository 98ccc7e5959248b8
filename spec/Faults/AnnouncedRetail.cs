using AcPhys.Contract;
using AcPhys.Core;

namespace AcPhys.Spec.Faults;

/// <summary>
/// An implementation that behaves in one mode and announces retail (<c>acphys serve --announce-retail</c>, the planted fault <c>ace-announced-retail</c>): a port that
/// deviates without declaring it. Every answer is the inner one; only the declared pick and fidelity say retail, so the
/// suite compares it with retail and must find each deviation (docs/facts-coverage.md, "Declared deviations").
/// </summary>
/// <param name="inner">The implementation whose answers are served.</param>
internal sealed class AnnouncedRetail(ICellPhysics inner) : ForwardingPhysics(inner)
{
    /// <inheritdoc/>
    public override string Name => Inner.Name + " (announced retail)";

    /// <inheritdoc/>
    public override PickPolicy Pick => PickPolicy.Retail;

    /// <inheritdoc/>
    public override IndoorFidelity Indoor => IndoorFidelity.Retail;

    /// <inheritdoc/>
    public override OutdoorFidelity Outdoor => OutdoorFidelity.Retail;
}
