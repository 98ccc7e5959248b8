using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>
/// Each port fault of issue #15 (<see cref="IndoorPortFaults"/>) by its defining worked example: a two-room cottage in
/// 0xA9B4 at (50, 50) (room 0 is x 50..56, room 1 x 56..62, y 50..56, front door y = 50, back door y = 56) where the
/// reference and the fault answer differently.
/// </summary>
public sealed class PortFaultExamples
{
    private static readonly CellId Room0 = new(0xA9B40100);
    private static readonly CellId Room1 = new(0xA9B40101);
    private static readonly CellId Owner = new(0xA9B40013);
    private static readonly CottagePlan Plan = new((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, true, false);
    private static readonly Scene Cottage = SceneKit.Cottage(Plan);

    [Fact(DisplayName = "building-first-portal-only: a sphere at the back door is entered into room 1 by the reference and not by the fault")]
    public void BackDoor() => Differ("building-first-portal-only", Cottage, Owner, [At(59, 56.3f)], r => r.Cells.Contains(Room1), f => !f.Cells.Contains(Room1));

    [Fact(DisplayName = "building-stop-first-room: with two doors into two unlinked rooms, a sphere touching both enters both in the reference and only room 0 with the fault")]
    public void StopFirstRoom()
    {
        var unlinked = Cottage with
        {
            Cells = [.. Cottage.Cells.Select(c => c with { Portals = [.. c.Portals.Where(p => p.IsExit)] })],
            Buildings = [Cottage.Buildings[0] with { Portals = [new(0x100, 0), new(0x101, 0)] }],
        };
        Differ("building-stop-first-room", unlinked, Owner, [At(55.8f, 50.2f)], r => r.Cells.Contains(Room1), f => !f.Cells.Contains(Room1));
    }

    [Fact(DisplayName = "snapshot-closure: a sphere at the front door next to the inner wall reaches room 1 through room 0 only when the closure walks the growing array")]
    public void Snapshot() => Differ("snapshot-closure", SceneKit.Cottage(Plan with { BackDoor = false }), Owner, [At(55.8f, 50.3f)], r => r.Cells.Contains(Room1), f => !f.Cells.Contains(Room1));

    [Fact(DisplayName = "exit-straddle-one-sided: deep inside room 0 a transition query adds no land cell in the reference and the land cells with the fault")]
    public void OneSidedExit() => Differ("exit-straddle-one-sided", Cottage, Room0, [At(53, 53)], r => !r.Cells.Any(c => c.IsLand), f => f.Cells.Contains(Owner), loadCells: true);

    [Fact(DisplayName = "invalid-bld-portal-entered: a building portal with OtherPortalId 0xFFFF is skipped by the reference and entered by the fault")]
    public void InvalidPortal()
    {
        var invalid = Cottage with { Buildings = [Cottage.Buildings[0] with { Portals = [new(0x100, 0xFFFF)] }] };
        Differ("invalid-bld-portal-entered", invalid, Owner, [At(53, 51)], r => r.Containing == Owner, f => f.Containing == Room0);
    }

    [Fact(DisplayName = "neighbour-by-plane: a sphere 0.505 m from the inner wall reaches room 1's padded volume (reference) but not the wall's plane within r + EPS (fault)")]
    public void ByPlane() => Differ("neighbour-by-plane", Cottage, Room0, [At(55.495f, 53)], r => r.Cells.Contains(Room1), f => !f.Cells.Contains(Room1));

    [Fact(DisplayName = "sphere-test-unpadded: a sphere 0.505 m from room 1 intersects it with the BSP's 0.01 padding and not without")]
    public void Unpadded() => Differ("sphere-test-unpadded", Cottage, Room0, [At(55.495f, 53)], r => r.Cells.Contains(Room1), f => !f.Cells.Contains(Room1));

    [Fact(DisplayName = "pick-last-env: a centre on the shared inner wall is in both rooms; the reference picks the first (room 0), the fault the last (room 1)")]
    public void LastEnv() => Differ("pick-last-env", Cottage, Room0, [At(56, 53)], r => r.Containing == Room0, f => f.Containing == Room1);

    [Fact(DisplayName = "close-is-outside: a centre on the shared inner wall is in room 0 for the reference and in no cell with the fault")]
    public void CloseOutside() => Differ("close-is-outside", Cottage, Room0, [At(56, 53)], r => r.Containing == Room0, f => f.Containing.IsNone);

    [Fact(DisplayName = "pick-last-sphere: sphere 0 in room 0 and sphere 1 in room 1 are picked into room 0 by the reference and room 1 by the fault")]
    public void LastSphere() => Differ("pick-last-sphere", Cottage, Room0, [At(55.5f, 53), At(56.5f, 53)], r => r.Containing == Room0, f => f.Containing == Room1);

    [Fact(DisplayName = "transit-sphere0-only: sphere 1 crossing the front door enters room 0 in the reference, not with the fault")]
    public void Sphere0Only() => Differ("transit-sphere0-only", Cottage, Owner, [At(53, 48.5f), At(53, 50.3f)], r => r.Cells.Contains(Room0), f => !f.Cells.Contains(Room0));

    [Fact(DisplayName = "hits-interior-unset: a sphere straddling the front door with its centre outside sets HitsInteriorCell in the reference, not with the fault")]
    public void HitsUnset() => Differ("hits-interior-unset", Cottage, Owner, [At(53, 49.8f)], r => r.HitsInteriorCell == true, f => f.HitsInteriorCell == false && f.Cells.Contains(Room0));

    [Fact(DisplayName = "pick-before-transit: a centre 1 m inside the front door is picked into room 0 by the reference and stays on land with the fault")]
    public void PickFirst() => Differ("pick-before-transit", Cottage, Owner, [At(53, 51)], r => r.Containing == Room0, f => f.Containing == Owner);

    [Fact(DisplayName = "early-return-undeclared: straddling the front door from room 0 with the centre inside, the static filter drops the land cells in the reference, not with the fault")]
    public void EarlyReturn() => Differ("early-return-undeclared", Cottage, Room0, [At(53, 50.2f)], r => r.Cells.SequenceEqual([Room0]), f => f.Cells.Contains(Owner));

    [Fact(DisplayName = "filter-drops-hints: with room 1 unloaded, a static query reaching into it keeps its load hint in the reference and drops it with the fault")]
    public void DropsHints() => Differ("filter-drops-hints", WithRoom1Unloaded(), Room0, [At(55.8f, 53)], r => r.Cells.Contains(Room1), f => !f.Cells.Contains(Room1));

    [Fact(DisplayName = "hint-straddle-only: with room 1 unloaded, a sphere wholly past the inner wall is hinted by the reference and not with the fault")]
    public void HintStraddle() => Differ("hint-straddle-only", WithRoom1Unloaded(), Room0, [At(56.6f, 53)], r => r.Cells.Contains(Room1), f => !f.Cells.Contains(Room1));

    [Fact(DisplayName = "neighbour-wrong-frame: with room 1 in its own frame 20 m north, a sphere crossing the inner door enters room 1 only when tested in room 1's frame")]
    public void WrongFrame()
    {
        var shift = new Vector3(0, 20, 0);
        var reframed = Cottage with
        {
            Cells = [.. Cottage.Cells.Select(c => c.Id != Room1 ? c : c with
            {
                Origin = c.Origin + shift,
                Pieces = [.. c.Pieces.Select(p => ScenePiece.FromBox(p.Box!.Value.Min - shift, p.Box.Value.Max - shift))],
            })],
        };
        Differ("neighbour-wrong-frame", reframed, Room0, [At(56.3f, 53)], r => r.Containing == Room1, f => !f.Cells.Contains(Room1));
    }

    [Fact(DisplayName = "walks-negative-children: a centre in room 0's second piece is in no cell for retail's positive chain and in room 0 with the fault")]
    public void NegativeChildren()
    {
        var twoPiece = Cottage with
        {
            Cells = [.. Cottage.Cells.Select(c => c.Id != Room0 ? c : c with { Pieces = [c.Pieces[0], ScenePiece.FromBox(new Vector3(0, -4, 0), new Vector3(6, 0, 3))] })],
        };
        Differ("walks-negative-children", twoPiece, Room0, [At(53, 47)], r => r.Containing != Room0, f => f.Containing == Room0);
    }

    private static Sphere At(float x, float y) => new(new Vector3(x, y, 0.5f), 0.5f);

    private static Scene WithRoom1Unloaded() => Cottage with { Cells = [.. Cottage.Cells.Where(c => c.Id != Room1)], UnloadedCells = [Room1] };

    private static void Differ(string faultId, Scene scene, CellId position, Sphere[] spheres, Func<FindCellResult, bool> reference, Func<FindCellResult, bool> faulty, bool loadCells = false)
    {
        var r = ReferenceAdapter.Instance.FindCell(scene, position, spheres, CellId.None, loadCells);
        var f = PlantedFaults.Create(faultId).FindCell(scene, position, spheres, CellId.None, loadCells);
        Assert.True(reference(r), $"reference: {AcPhys.Spec.Invariants.Conformance.Show(r)} → {r.Containing}, hits {r.HitsInteriorCell}");
        Assert.True(faulty(f), $"{faultId}: {AcPhys.Spec.Invariants.Conformance.Show(f)} → {f.Containing}, hits {f.HitsInteriorCell}");
    }
}
