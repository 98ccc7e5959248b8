using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Scenes;
using AcPhys.Protocol.Messages;
using AcPhys.Protocol.Server;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>
/// The parts cell list over a scene (find_cell_parts_scene / find_cell_parts_transition; facts §3.4, §4 step 5, §5.2,
/// §5.3) on the two-room cottage in 0xA9B4 at (50, 50): the reference's answers, and the same answers served.
/// </summary>
public sealed class PartsSceneQueryFacts
{
    private static readonly CellId Room0 = new(0xA9B40100);
    private static readonly CellId Room1 = new(0xA9B40101);
    private static readonly CellId Owner = new(0xA9B40013);
    private static readonly Scene Cottage = SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, false, false));

    private static Part At(CellId cell, float x, float y) => new(cell, new Frame(new Vector3(x, y, 1), Quaternion.Identity), new Box(new Vector3(-0.2f), new Vector3(0.2f)), 0.5f, false);

    [Fact(DisplayName = "facts §5.2: an indoor anchor deep in a room lists its room alone, loaded, HitsInteriorCell set, no containing cell")]
    public void DeepInARoom()
    {
        var r = ReferenceAdapter.Instance.FindCellParts(Cottage, [At(Room0, 53, 53)], false);
        Assert.Equal([Room0], r.Cells);
        Assert.Equal([true], r.Loaded!);
        Assert.True(r.HitsInteriorCell);
        Assert.Equal(CellId.None, r.Containing);
    }

    [Fact(DisplayName = "facts §5.2: a part straddling the inner door adds the next room; a second part does it when the first does not")]
    public void InnerDoorByAnyPart()
    {
        Assert.Equal([Room0, Room1], ReferenceAdapter.Instance.FindCellParts(Cottage, [At(Room0, 55.9f, 53)], false).Cells);
        Assert.Equal([Room0, Room1], ReferenceAdapter.Instance.FindCellParts(Cottage, [At(Room0, 53, 53), At(Room0, 55.9f, 53)], false).Cells);
    }

    [Fact(DisplayName = "facts §5.2, §4 step 5: at the exit a transition keeps the land cells the parts variant adds; static placement filters them out")]
    public void ExitTransitionVersusStatic()
    {
        var transition = ReferenceAdapter.Instance.FindCellParts(Cottage, [At(Room0, 53, 50.1f)], true);
        Assert.Contains(Owner, transition.Cells);
        Assert.Equal(Room0, transition.Cells[0]);
        var placed = ReferenceAdapter.Instance.FindCellParts(Cottage, [At(Room0, 53, 50.1f)], false);
        Assert.Equal([Room0], placed.Cells);
    }

    [Fact(DisplayName = "facts §5.3: an outdoor anchor whose box crosses the front door enters the building (HitsInteriorCell); one far from it does not")]
    public void OutdoorAnchorEntersTheBuilding()
    {
        var entering = ReferenceAdapter.Instance.FindCellParts(Cottage, [At(Owner, 53, 49.9f)], false);
        Assert.Equal(Owner, entering.Cells[0]);
        Assert.Contains(Room0, entering.Cells);
        Assert.True(entering.HitsInteriorCell);
        var away = ReferenceAdapter.Instance.FindCellParts(Cottage, [At(Owner, 53, 44)], false);
        Assert.DoesNotContain(away.Cells, c => c.IsEnv);
        Assert.False(away.HitsInteriorCell);
    }

    [Fact(DisplayName = "protocol v1: find_cell_parts_scene and find_cell_parts_transition served answer as the reference in process; a scene-less request and an op not offered are clear errors")]
    public void ServedAsTheReference()
    {
        var server = new ProtocolServer(ReferenceAdapter.Instance);
        Part[][] queries = [[At(Room0, 53, 53)], [At(Room0, 55.9f, 53)], [At(Room0, 53, 50.1f)], [At(Owner, 53, 49.9f), At(Owner, 53, 44)]];
        foreach (var parts in queries)
        {
            foreach (bool loadCells in new[] { false, true })
            {
                var expected = ReferenceAdapter.Instance.FindCellParts(Cottage, parts, loadCells);
                var row = loadCells ? MessageTable.FindCellPartsTransition : MessageTable.FindCellPartsScene;
                string request = Wire.Line(w =>
                {
                    w.WriteString("op", row.Name);
                    w.WritePropertyName("scene");
                    w.WriteRawValue(SceneJson.WriteCompact(Cottage));
                    row.WriteRequest(w, new PartsInScene(Cottage, parts));
                });
                using var answer = Wire.Parse(server.Answer(request));
                var got = Answers.FindCell.Read(answer.RootElement);
                Assert.Equal(expected.Cells, got.Cells);
                Assert.Equal(expected.Loaded, got.Loaded);
                Assert.Equal(expected.HitsInteriorCell, got.HitsInteriorCell);
                Assert.Equal(CellId.None, got.Containing);
            }
        }

        string sceneless = Wire.Line(w =>
        {
            w.WriteString("op", "find_cell_parts_scene");
            w.WriteNull("scene");
            MessageTable.FindCellPartsScene.WriteRequest(w, new PartsInScene(null, [At(Room0, 53, 53)]));
        });
        Assert.Contains("needs a scene", server.Answer(sceneless), StringComparison.Ordinal);
        var withoutParts = new ProtocolServer(new OpsOffered(ReferenceAdapter.Instance, Op.All & ~Op.FindCellPartsTransition));
        string transition = Wire.Line(w =>
        {
            w.WriteString("op", "find_cell_parts_transition");
            w.WritePropertyName("scene");
            w.WriteRawValue(SceneJson.WriteCompact(Cottage));
            MessageTable.FindCellPartsTransition.WriteRequest(w, new PartsInScene(Cottage, [At(Room0, 53, 53)]));
        });
        Assert.Contains("not offered", withoutParts.Answer(transition), StringComparison.Ordinal);
    }

    [Fact(DisplayName = "contract: an implementation that does not override FindCellParts answers NotSupportedException, naming the op (NOT TESTED, never a failure)")]
    public void DefaultIsNotSupported()
    {
        ICellPhysics bare = new Bare();
        Assert.Throws<NotSupportedException>(() => bare.FindCellParts(Cottage, [At(Room0, 53, 53)], false));
        var e = Assert.Throws<NotSupportedException>(() => bare.FindCellParts(Cottage, [At(Room0, 53, 53)], true));
        Assert.Equal("find_cell_parts_transition", e.Message);
        Assert.Equal(Op.None, bare.Ops & (Op.FindCellPartsScene | Op.FindCellPartsTransition));
    }

    // Only what the interface requires: FindCellParts is its default.
    private sealed class Bare : ICellPhysics
    {
        public string Name => "bare";

        public Op Ops => Op.OpenLand;

        public PickPolicy Pick => PickPolicy.Retail;

        public bool BlockIdToLcoord(CellId id, out Lcoord lcoord) => ReferenceAdapter.Instance.BlockIdToLcoord(id, out lcoord);

        public bool GidToLcoord(CellId id, out Lcoord lcoord) => ReferenceAdapter.Instance.GidToLcoord(id, out lcoord);

        public CellId LcoordToGid(int x, int y) => ReferenceAdapter.Instance.LcoordToGid(x, y);

        public bool InboundValidCellId(CellId id) => ReferenceAdapter.Instance.InboundValidCellId(id);

        public bool GetOutsideLcoord(CellId id, float x, float y, out Lcoord lcoord) => ReferenceAdapter.Instance.GetOutsideLcoord(id, x, y, out lcoord);

        public AdjustResult AdjustToOutside(CellId id, float x, float y) => ReferenceAdapter.Instance.AdjustToOutside(id, x, y);

        public IReadOnlyList<CellId> OutsideCells(CellId cell, IReadOnlyList<Sphere> spheres) => ReferenceAdapter.Instance.OutsideCells(cell, spheres);

        public FindCellResult FindCell(CellId cell, IReadOnlyList<Sphere> spheres, CellId current) => ReferenceAdapter.Instance.FindCell(cell, spheres, current);

        public IReadOnlyList<CellId> OutsideCellsParts(IReadOnlyList<Part> parts) => ReferenceAdapter.Instance.OutsideCellsParts(parts);
    }
}
