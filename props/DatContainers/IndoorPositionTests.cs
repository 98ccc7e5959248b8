using System.Diagnostics;
using System.Numerics;
using AcPhys.Contract;
using AcPhys.Formats.Dat.Container;
using AcPhys.Props.Dat;
using AcPhys.Props.Support;
using AcPhys.Spec.Running;
using Xunit.Abstractions;

namespace AcPhys.Props.DatContainers;

/// <summary>
/// DAT-INDOOR-POSITIONS: with a dat world, a stored indoor position is checked by find_cell naming the stored env cell,
/// or counted by the reason it could not be; on the corpus world here, on the user's retail files when
/// ACPHYS_CELL_DAT and ACPHYS_PORTAL_DAT name them.
/// </summary>
public sealed class IndoorPositionTests(ITestOutputHelper output)
{
    [Fact(DisplayName = "DAT-INDOOR-POSITIONS: on the corpus dat world, every cell's centre agrees, a position outside its cell names another, rows the file cannot check are counted by reason")]
    public void CorpusWorld()
    {
        var scenes = DatTestSupport.CorpusSceneWalks.Select(e => e.Entry.SceneWalk!.Scene).ToList();
        var (cell, portal) = SceneContainers.Records(scenes);
        using var world = new DatWorld(
            DatContainer.Open(new MemoryBlockSource(DatContainerWriter.ToBytes(cell, DatSet.Cell, 256), "cell.dat")),
            DatContainer.Open(new MemoryBlockSource(DatContainerWriter.ToBytes(portal, DatSet.Portal, 256), "portal.dat")));
        var inside = scenes.SelectMany(s => s.Cells).DistinctBy(c => c.Id).Select(c =>
        {
            var box = c.Pieces[0].Box!.Value;
            var local = ((box.Min + box.Max) / 2) with { Z = box.Min.Z };
            return new IndoorPosition(c.Id, c.Origin + Vector3.Transform(local, c.Rotation));
        }).ToList();
        var first = inside[0];
        IndoorPosition[] rows =
        [
            .. inside,
            first with { Position = first.Position + new Vector3(0, 0, 50) }, // far above its room
            first with { Cell = new AcPhys.Core.CellId(0x01010100) },        // a block the file does not hold
            first with { Cell = first.Cell.WithLow(0x0150) },                 // a cell the file does not hold
        ];

        var result = IndoorPositionCheck.Run(world, ReferenceAdapter.Instance, rows);
        output.WriteLine(result.ToString());
        Assert.Equal(inside.Count, result.Agreeing);
        Assert.Equal(1, result.ByReason[IndoorPositionResult.NamesAnother]);
        Assert.Equal(1, result.ByReason["block not in the cell dat"]);
        Assert.Equal(1, result.ByReason["stored cell not in the cell dat"]);
        Assert.Equal(rows.Length, result.ByReason.Values.Sum());
    }

    [RetailDatFact(DisplayName = "DAT-INDOOR-POSITIONS (retail files, ACPHYS_CELL_DAT / ACPHYS_PORTAL_DAT): every indoor row of retail-positions.tsv is checked or counted by reason")]
    public void RetailWorld()
    {
        var clock = Stopwatch.StartNew();
        using var world = DatWorld.Open(RetailDatFactAttribute.Cell!, RetailDatFactAttribute.Portal!);
        output.WriteLine($"opened in {clock.Elapsed.TotalSeconds:0.00} s: {world.Cell}; {world.Portal}");
        var rows = IndoorPositionsFile.Read(RequiresSharedDataFactAttribute.DataFile, out int skipped);
        var result = IndoorPositionCheck.Run(world, ReferenceAdapter.Instance, rows);
        output.WriteLine($"{result} ({skipped} rows did not parse); {clock.Elapsed.TotalSeconds:0.0} s in all; {world.Cell.Work}");
        foreach (var (row, got) in result.Disagreements)
        {
            output.WriteLine($"  {row.Cell} at ({row.Position.X}, {row.Position.Y}, {row.Position.Z}): find_cell names {got}");
        }

        Assert.Equal(144_504, rows.Count + skipped); // data/README.md: the indoor rows
        Assert.Equal(rows.Count, result.ByReason.Values.Sum());
        Assert.True(world.Landblocks().Any(), "the cell dat holds no Landblock record: not a cell database");
    }
}
