using AcPhys.Contract;
using AcPhys.Props.Support;
using AcPhys.Spec.Invariants;
using Xunit.Abstractions;

namespace AcPhys.Props.Indoor;

/// <summary>Each scene invariant as an FsCheck property against the reference core (retail, and current-first where it matters).</summary>
public sealed class IndoorInvariantProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "INTERIOR-WINS: an env candidate containing the centre beats every land cell")]
    public void InteriorWins() => PropertyRun.Check(IndoorInvariants.InteriorWins, output);

    [Fact(DisplayName = "HYSTERESIS-INDOOR: current-first keeps a current cell that still contains the centre")]
    public void HysteresisIndoor() => PropertyRun.Check(IndoorInvariants.HysteresisIndoor, output, ReferenceAdapter.CurrentFirst);

    [Fact(DisplayName = "PORTAL-TRANSIT: membership follows the body through portals within a step; load hints follow PortalSide")]
    public void PortalTransit() => PropertyRun.Check(IndoorInvariants.PortalTransit, output);

    [Fact(DisplayName = "PORTAL-TRANSIT (current-first): hysteresis never makes an absorbing state")]
    public void PortalTransitCurrentFirst() => PropertyRun.Check(IndoorInvariants.PortalTransit, output, ReferenceAdapter.CurrentFirst);

    [Fact(DisplayName = "NO-TUNNEL: the current cell moves only to neighbours and portal-linked cells")]
    public void NoTunnel() => PropertyRun.Check(IndoorInvariants.NoTunnel, output);

    [Fact(DisplayName = "VISIBILITY: indoors every loaded candidate is the cell or in its VisibleCells")]
    public void Visibility() => PropertyRun.Check(IndoorInvariants.Visibility, output);

    [Fact(DisplayName = "ENTER-EXIT: in and back out the same way ends in the start land cell")]
    public void EnterExit() => PropertyRun.Check(IndoorInvariants.EnterExit, output);

    [Fact(DisplayName = "SCENE-TRANSLATION: moving the scene by a block changes only the ids")]
    public void SceneTranslation() => PropertyRun.Check(IndoorInvariants.SceneTranslation, output);

    [Fact(DisplayName = "CONTAINING-CONTAINS: the containing cell contains the centre")]
    public void ContainingContains() => PropertyRun.Check(IndoorInvariants.ContainingContains, output);

    [Fact(DisplayName = "NEVER-NULL: a position over loaded land always has a containing cell")]
    public void NeverNull() => PropertyRun.Check(IndoorInvariants.NeverNull, output);

    [Fact(DisplayName = "SCENE-SOUNDNESS: every candidate is within reach of the body")]
    public void SceneSoundness() => PropertyRun.Check(IndoorInvariants.SceneSoundness, output);
}
