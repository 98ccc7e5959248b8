using System.Numerics;
using AcPhys.Contract;
using AcPhys.Core;
using AcPhys.Props.Mutation;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Scenes;

namespace AcPhys.Props.Indoor;

/// <summary>The port faults' query (<see cref="FaultySceneQuery"/>) without a defect is the reference core: a fault differs from it by its defect alone.</summary>
public sealed class FaultySceneQueryMatchesCore
{
    [Fact(DisplayName = "FaultySceneQuery with no defect answers every query of a grid over six cottages exactly as SceneQuery does, static and transition, hints and HitsInteriorCell included")]
    public void NoDefectIsTheReference()
    {
        CottagePlan[] plans =
        [
            new((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0f, 2, 6f, 6f, 0, true, false),
            new((0xA9 * 192.0) + 50, (0xB4 * 192.0) + 50, 0.7f, 3, 5f, 7f, 0b1011, true, true),
            new((0x40 * 192.0) + 186, (0x41 * 192.0) + 30, 0f, 4, 4f, 4f, 0b110, false, false),
            new((0x40 * 192.0) + 186, (0x41 * 192.0) + 30, 2.1f, 1, 6f, 5f, 1, true, true, LoadNeighbours: false),
            new((0x12 * 192.0) + 100, (0x34 * 192.0) + 188, 4f, 2, 7f, 6f, 0b11, false, true),
            new((0x12 * 192.0) + 100, (0x34 * 192.0) + 100, 0f, 4, 8f, 8f, 0xFF, true, true),
        ];
        var a = new CellArray();
        var b = new CellArray();
        int queries = 0;
        foreach (var plan in plans)
        {
            var scene = SceneKit.Cottage(plan);
            var built = SceneBuild.Build(scene);
            var ids = scene.Cells.Select(c => c.Id).ToArray();
            for (float x = -3; x < (plan.Rooms * plan.Width) + 3; x += 0.37f)
            {
                for (float y = -3; y < plan.Depth + 3; y += 0.41f)
                {
                    var p = plan.ToBlock(new Vector3(x, y, 0.5f));
                    var land = plan.Block.BlockCell;
                    if (!LandDefs.AdjustToOutside(ref land, ref p))
                    {
                        continue;
                    }

                    Sphere[] spheres = [new(p, 0.45f), new(p + new Vector3(0, 0, 1.1f), 0.45f)];
                    foreach (var position in ids.Where(id => id.Landblock == land.Landblock).Append(land))
                    {
                        foreach (bool loadCells in new[] { false, true })
                        {
                            var want = SceneQuery.FindCellList(a, built, position, spheres, CellId.None, new CellQueryOptions(PickPolicy.Retail, true, loadCells));
                            var got = FaultySceneQuery.FindCellList(b, built, position, spheres, loadCells, IndoorDefect.None);
                            Assert.Equal(want, got);
                            Assert.Equal(CellArrays.Entries(a), CellArrays.Entries(b));
                            queries++;
                        }
                    }
                }
            }
        }

        Assert.True(queries > 10_000, $"only {queries} queries");
    }
}
