using System.CommandLine;
using AcPhys.Formats.Dat.Container;
using AcPhys.Formats.Scenes;

namespace AcPhys.Cli.Commands;

/// <summary>
/// <c>scene from-dat</c>: the scene a walk at a place needs, extracted from a cell and a portal database
/// (docs/dat-container.md "Scenes from a dat world"). The library does the work (<see cref="SceneExtraction"/>); this
/// parses, opens, prints and writes.
/// </summary>
internal static class SceneFromDat
{
    /// <summary>Builds the subcommand.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var cell = new Option<string>("--cell") { Description = "The cell database (client_cell_1.dat, or one written by the container writer).", HelpName = "FILE", Required = true };
        var portal = new Option<string>("--portal") { Description = "The portal database (client_portal.dat).", HelpName = "FILE", Required = true };
        var landblock = new Option<string>("--landblock") { Description = "The landblock of the place, 0xAABB.", HelpName = "0xAABB", Required = true };
        var around = new Option<string?>("--around") { Description = "A point in the block frame and a radius, metres (X,Y,R in 0..192): keep the env cells whose origin lies within R, the cells behind doors of buildings within R, and what their portals reach. Without it: every door and every env cell of the block.", HelpName = "X,Y,R" };
        var maxCells = new Option<int>("--max-cells") { Description = $"The most env cells to keep (1..{SceneRules.MaxItems}); the rest become load hints.", DefaultValueFactory = _ => SceneExtraction.DefaultMaxCells };
        var output = new Option<string>("--output", "-o") { Description = "The scene JSON to write, atomically.", HelpName = "FILE", Required = true };
        var command = new Command("from-dat", "Write the scene a walk at a place needs, read from a cell and a portal dat: the landblocks, buildings, env cells reachable through portals, unloaded neighbours as load hints.") { cell, portal, landblock, around, maxCells, output };
        command.SetAction(parse => Guard.Run("scene from-dat", () => Run(
            parse.GetValue(cell) ?? string.Empty,
            parse.GetValue(portal) ?? string.Empty,
            parse.GetValue(landblock) ?? string.Empty,
            parse.GetValue(around),
            parse.GetValue(maxCells),
            parse.GetValue(output) ?? string.Empty)));
        return command;
    }

    /// <summary>Parses a place: a block and an optional <c>X,Y,R</c>.</summary>
    /// <param name="landblock">The block text.</param>
    /// <param name="around">The point and radius, or null.</param>
    /// <returns>The place.</returns>
    /// <exception cref="UsageException">Either is malformed.</exception>
    public static ScenePlace Place(string landblock, string? around)
    {
        if (!ScenePlace.TryParseBlock(landblock, out var block))
        {
            throw new UsageException($"--landblock {(landblock.Length == 0 ? "''" : landblock)}: expected a landblock on the map, 0xAABB (AA and BB at most 0xFE)");
        }

        if (around is null)
        {
            return new ScenePlace(block);
        }

        return ScenePlace.TryParseAround(block, around, out var place)
            ? place
            : throw new UsageException($"--around {(around.Length == 0 ? "''" : around)}: expected X,Y,R: three numbers, each 0..192 (metres in the block frame)");
    }

    /// <summary>Opens a dat world, turning a missing or unreadable file into a usage error.</summary>
    /// <param name="cell">The cell database path.</param>
    /// <param name="portal">The portal database path.</param>
    /// <param name="cellOption">The option naming the cell database, for messages.</param>
    /// <param name="portalOption">The option naming the portal database, for messages.</param>
    /// <returns>The world.</returns>
    /// <exception cref="UsageException">A file is missing or cannot be opened.</exception>
    /// <exception cref="DatContainerException">A file is not a readable container (exit 5).</exception>
    public static DatWorld OpenWorld(string cell, string portal, string cellOption, string portalOption)
    {
        foreach (var (option, path) in new[] { (cellOption, cell), (portalOption, portal) })
        {
            if (!File.Exists(path))
            {
                throw new UsageException($"{option} {(path.Length == 0 ? "''" : path)}: no such file");
            }
        }

        try
        {
            return DatWorld.Open(cell, portal);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new UsageException($"cannot open the dat files: {e.Message}", e);
        }
    }

    private static int Run(string cell, string portal, string landblock, string? around, int maxCells, string output)
    {
        OutputPath.Check("-o", output);
        OutputPath.CheckDistinct([("-o", output)], [cell, portal]);
        var place = Place(landblock, around);
        if (maxCells < 1 || maxCells > SceneRules.MaxItems)
        {
            throw new UsageException($"--max-cells {maxCells}: expected 1..{SceneRules.MaxItems}");
        }

        using var world = OpenWorld(cell, portal, "--cell", "--portal");
        if (!world.Cell.Contains(SceneExtraction.LandblockRecordId(place.Block)))
        {
            throw new UsageException($"--landblock {place.Block}: {cell} holds no Landblock record {AcPhys.Formats.Dat.RecordIds.Text(SceneExtraction.LandblockRecordId(place.Block))} ({world.Landblocks().Count()} landblocks in the file)");
        }

        var got = SceneExtraction.Extract(world, place, maxCells);
        OutputPath.Write(output, SceneJson.Write(got.Scene));
        Terminal.Line($"scene from-dat: {got.Report}");
        Terminal.Line($"scene from-dat: wrote {output} ({got.Scene}); read {got.Report.Work}");
        return ExitCodes.Ok;
    }
}
