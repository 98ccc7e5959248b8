using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Formats.Dat;
using Xunit.Abstractions;

namespace AcPhys.Props.Dat;

/// <summary>DAT-GEOMETRY-KEY: cells share a CellStruct exactly when their pieces and portal planes are bit-equal.</summary>
public sealed class CellGeometryKeyProperties(ITestOutputHelper output)
{
    [Fact(DisplayName = "DAT-GEOMETRY-KEY: on 2,000 generated scenes, two cells have equal keys exactly when their written CellStructs are byte-equal.")]
    public void KeysAgreeWithTheStructsWritten()
    {
        int pairs = 0, equal = 0, cells = 0;
        foreach (var scene in DatTestSupport.Generated(1000, 0x6E0).Concat(DatTestSupport.MultiPiece(1000, 0x6E1)))
        {
            var keyed = scene.Cells.Select(c => (Key: CellGeometryKey.Of(c), Bytes: StructBytes(c))).ToArray();
            cells += keyed.Length;
            for (int i = 0; i < keyed.Length; i++)
            {
                for (int j = i + 1; j < keyed.Length; j++)
                {
                    pairs++;
                    bool sameKey = keyed[i].Key.Equals(keyed[j].Key);
                    equal += sameKey ? 1 : 0;
                    Assert.Equal(keyed[i].Bytes.AsSpan().SequenceEqual(keyed[j].Bytes), sameKey);
                    Assert.True(!sameKey || keyed[i].Key.GetHashCode() == keyed[j].Key.GetHashCode());
                }
            }
        }

        output.WriteLine($"{cells} cells, {pairs} pairs, {equal} with equal keys");
        Assert.True(equal > 0 && equal < pairs, "the sample needs both equal and different geometries");
    }

    [Fact(DisplayName = "DAT-GEOMETRY-KEY: one float step in a piece plane, a portal plane, or a piece more or fewer gives another key; id, frame and visible cells do not.")]
    public void OneBitApartIsAnotherKey()
    {
        var box = ScenePiece.FromBox(Vector3.Zero, new Vector3(4, 4, 3));
        var portal = new ScenePortal(new CellPlane(Vector3.UnitX, 0), 0xFFFF, true);
        var cell = new SceneCell(new CellId(0xA9B40100), Vector3.Zero, Quaternion.Identity, [box], [portal], []);
        var key = CellGeometryKey.Of(cell);

        var elsewhere = cell with { Id = new CellId(0xA9B40105), Origin = new Vector3(10, 20, 0), Visible = [new CellId(0xA9B40100)] };
        Assert.Equal(key, CellGeometryKey.Of(elsewhere));
        Assert.Equal(key.GetHashCode(), CellGeometryKey.Of(elsewhere).GetHashCode());

        var wider = cell with { Pieces = [ScenePiece.FromBox(Vector3.Zero, new Vector3(MathF.BitIncrement(4f), 4, 3))] };
        var portalMoved = cell with { Portals = [portal with { Plane = new CellPlane(Vector3.UnitX, MathF.BitIncrement(0f)) }] };
        var twoPieces = cell with { Pieces = [box, ScenePiece.FromBox(new Vector3(4, 0, 0), new Vector3(6, 4, 3))] };
        var noPortal = cell with { Portals = [] };
        foreach (var other in new[] { wider, portalMoved, twoPieces, noPortal })
        {
            Assert.NotEqual(key, CellGeometryKey.Of(other));
        }
    }

    // The CellStruct bytes a scene of this one cell writes (its key is 0 either way).
    private static byte[] StructBytes(SceneCell cell) =>
        DatTestSupport.StructBytes(DatSceneWriter.Write(new Scene([cell.Id.Landblock], [], [cell]), "test", "memory"));
}
