using System.Numerics;
using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>One bite: an invariant, a defective test adapter, and a concrete scene walk on which the reference holds (or rightly has nothing to check) and the defect is violated.</summary>
/// <param name="Invariant">The invariant.</param>
/// <param name="Defect">The defective adapter.</param>
/// <param name="Case">The scene walk.</param>
/// <param name="ReferenceApplies">False when the reference's answer has nothing the invariant applies to (Vacuous).</param>
internal sealed record ExactBite(Invariant<SceneWalk> Invariant, DefectiveSceneAdapter Defect, SceneWalk Case, bool ReferenceApplies = true);

/// <summary>The exact indoor invariants' bites (props/Indoor/IndoorExactInvariantProperties.cs runs each; PlantedFaultsAreCaught counts them as teeth).</summary>
internal static class ExactBites
{
    private static readonly CottagePlan BackDoorPlan = ExactSceneCases.BackDoor;
    private static readonly CottagePlan FrontOnlyPlan = ExactSceneCases.FrontOnly;
    private static readonly Scene BackDoor = SceneKit.Cottage(BackDoorPlan);
    private static readonly Scene FrontOnly = SceneKit.Cottage(FrontOnlyPlan);
    private static readonly Vector3 AtFrontDoorOutside = new(3, -0.2f, 1);

    public static ExactBite HitsOnlyFromPick { get; } = new(IndoorExactInvariants.HitsInterior, ExactDefects.HitsOnlyFromPick, ExactSceneCases.At(BackDoor, BackDoorPlan, AtFrontDoorOutside));

    public static ExactBite SnapshotClosure { get; } = new(IndoorClosureInvariants.NeighboursComplete, ExactDefects.SnapshotClosure, ExactSceneCases.At(FrontOnly, FrontOnlyPlan, new Vector3(5.8f, -0.2f, 1)));

    public static ExactBite SecondBuildingPortal { get; } = new(IndoorClosureInvariants.BuildingEntryComplete, ExactDefects.DropsSecondBuildingPortal, ExactSceneCases.At(BackDoor, BackDoorPlan, new Vector3(9, 5.2f, 1)));

    public static ExactBite NeighbourByPlane { get; } = new(IndoorClosureInvariants.EnvCandidateJustified, ExactDefects.NeighbourByPlane, ExactSceneCases.At(FrontOnly, FrontOnlyPlan, AtFrontDoorOutside, null, new Vector3(3, -6, 0)));

    public static ExactBite InvalidBuildingPortal { get; } = new(IndoorClosureInvariants.EnvCandidateJustified, ExactDefects.EntersInvalidBuildingPortal, ExactSceneCases.At(ExactSceneCases.InvalidBackDoor(), BackDoorPlan, new Vector3(9, 5.2f, 1)), ReferenceApplies: false);

    public static ExactBite ExitWithoutStraddle { get; } = new(IndoorExactInvariants.LandViaExit, ExactDefects.ExitWithoutStraddle, ExactSceneCases.At(BackDoor, BackDoorPlan, new Vector3(3, 2.5f, 1), BackDoorPlan.RoomId(0)));

    public static ExactBite NoOutdoorCellsOnExit { get; } = new(IndoorExactInvariants.LandViaExit, ExactDefects.NoOutdoorCellsOnExit, ExactSceneCases.At(BackDoor, BackDoorPlan, new Vector3(3, 0.2f, 1), BackDoorPlan.RoomId(0)));

    public static ExactBite LastEnvWins { get; } = new(IndoorExactInvariants.PickFirstEnv, ExactDefects.LastEnvWins, ExactSceneCases.Overlap());

    public static ExactBite LastSphereDecides { get; } = new(IndoorExactInvariants.PickFirstEnv, ExactDefects.LastSphereDecides, ExactSceneCases.At(FrontOnly, FrontOnlyPlan, new Vector3(5.5f, 2.5f, 1), FrontOnlyPlan.RoomId(0), new Vector3(1, 0, 0)));

    /// <summary>Gets every bite.</summary>
    public static IReadOnlyList<ExactBite> All { get; } =
        [HitsOnlyFromPick, SnapshotClosure, SecondBuildingPortal, NeighbourByPlane, InvalidBuildingPortal, ExitWithoutStraddle, NoOutdoorCellsOnExit, LastEnvWins, LastSphereDecides];
}
