using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>
/// The declared mode <c>ace-box-side-pairing</c> (facts §5.3, §7 #14) on the two-room cottage in 0xA9B4 at (50, 50), whose
/// front door is the plane y = 50 with room 0 on its y &gt; 50 side: a part standing on land whose box lies wholly on one
/// side of the door while its sphere reaches across is where retail's pairing and ACE's differ. Core, the reference in
/// the declared mode and the fidelity names, independent of any walk generator.
/// </summary>
public sealed class AceBoxSidePairingFacts
{
    private static readonly CellId Room0 = new(0xA9B40100);
    private static readonly CellId Owner = new(0xA9B40013);
    private static readonly Scene Cottage = SceneKit.Cottage(new CottagePlan((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, false, false));

    // Box half-side 0.2, sphere r 0.5: at y = 50.3 the box is 50.1..50.5 (wholly on the room's side) and the sphere crosses y = 50.
    private static Part At(float x, float y) => new(Owner, new Frame(new Vector3(x, y, 1), Quaternion.Identity), new Box(new Vector3(-0.2f), new Vector3(0.2f)), 0.5f, false);

    private static ReferenceAdapter Declaring(string name)
    {
        Assert.True(FidelityNames.TryParse([name], out var indoor, out var outdoor, out _));
        return new ReferenceAdapter(PickPolicy.Retail, outdoor: outdoor) { Indoor = indoor };
    }

    [Fact(DisplayName = "facts §5.3, §7 #14: core's parts cell list from land enters a room whose door a box wholly on the room's side reaches under retail's pairing, and not under IndoorFidelity.AceBoxSidePairing")]
    public void CoreFollowsTheSwitch()
    {
        var scene = SceneBuild.Build(Cottage);
        var retail = new CellArray();
        bool retailHits = ScenePartsQuery.FindCellList(retail, scene, [At(53, 50.3f)], false, IndoorFidelity.Retail);
        var ace = new CellArray();
        bool aceHits = ScenePartsQuery.FindCellList(ace, scene, [At(53, 50.3f)], false, IndoorFidelity.Retail with { AceBoxSidePairing = true });

        Assert.Contains(Room0, retail.ToIdArray());
        Assert.True(retailHits);
        Assert.DoesNotContain(Room0, ace.ToIdArray());
        Assert.False(aceHits);
        Assert.Equal(retail.ToIdArray().Where(c => c != Room0), ace.ToIdArray()); // the land cells are the same: only the door differs
    }

    [Fact(DisplayName = "facts §5.3, §7 #14: a box crossing the door plane enters under both pairings, with the same answer")]
    public void CrossingEntersUnderBoth()
    {
        var retail = ReferenceAdapter.Instance.FindCellParts(Cottage, [At(53, 50.05f)], false);
        var ace = Declaring("ace-box-side-pairing").FindCellParts(Cottage, [At(53, 50.05f)], false);
        Assert.Contains(Room0, retail.Cells);
        Assert.Equal(retail.Cells, ace.Cells);
        Assert.Equal(retail.Loaded!, ace.Loaded!);
        Assert.Equal(retail.HitsInteriorCell, ace.HitsInteriorCell);
    }

    [Theory(DisplayName = "facts §7 #14: the reference declaring ace-box-side-pairing (or ace, which bundles it) answers the parts query with ACE's pairing; retail and the other switches keep retail's")]
    [InlineData("ace-box-side-pairing", false)]
    [InlineData("ace", false)]
    [InlineData("ace-transition-filter", true)]
    [InlineData("ace-no-portal-guard", true)]
    public void DeclaredModeAnswers(string name, bool entersRoom)
    {
        var answer = Declaring(name).FindCellParts(Cottage, [At(53, 50.3f)], false);
        Assert.Equal(entersRoom, answer.Cells.Contains(Room0));
        Assert.Equal(entersRoom, answer.HitsInteriorCell);
    }

    [Fact(DisplayName = "facts §7 #14: ace-box-side-pairing is a fidelity name, parsed to the switch alone, named back, and part of ace")]
    public void IsADeclaredMode()
    {
        Assert.Contains("ace-box-side-pairing", FidelityNames.Known);
        Assert.True(FidelityNames.TryParse(["ace-box-side-pairing"], out var indoor, out var outdoor, out _));
        Assert.Equal(IndoorFidelity.Retail with { AceBoxSidePairing = true }, indoor);
        Assert.Equal(OutdoorFidelity.Retail, outdoor);
        Assert.Equal(["ace-box-side-pairing"], FidelityNames.Names(indoor, outdoor));
        Assert.True(IndoorFidelity.Ace.AceBoxSidePairing);
        Assert.Contains("ace-box-side-pairing", FidelityNames.Names(IndoorFidelity.Ace, OutdoorFidelity.Retail));
    }
}
