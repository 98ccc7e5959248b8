using System.CommandLine;
using AcPhys.Contract;
using AcPhys.Formats;
using AcPhys.Formats.Corpus;
using AcPhys.Formats.Dat.Container;
using AcPhys.Formats.Scenes;

namespace AcPhys.Cli.Commands;

/// <summary>
/// <c>scene to-dat</c>: scene-walk corpus files (or bare scenes) written as one dat world, a cell and a portal container
/// (docs/dat-container.md "Writing"), for fixtures and for trying <c>scene from-dat</c> and <c>verify --cell-dat</c>
/// without the game's files.
/// </summary>
internal static class SceneToDat
{
    /// <summary>Builds the subcommand.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var files = new Argument<string[]>("files") { Description = "Scene-walk corpus files or bare scene JSON files; their loaded blocks must not overlap (a scene given twice is written once).", Arity = ArgumentArity.OneOrMore };
        var cell = new Option<string>("--cell") { Description = "The cell database to write (atomically).", HelpName = "FILE", Required = true };
        var portal = new Option<string>("--portal") { Description = "The portal database to write (atomically).", HelpName = "FILE", Required = true };
        var blockSize = new Option<uint>("--block-size") { Description = "The block size of both containers (8..1048576).", DefaultValueFactory = _ => 1024 };
        var command = new Command("to-dat", "Write scenes as a dat world: a cell and a portal container in the retail layout.") { files, cell, portal, blockSize };
        command.SetAction(parse => Guard.Run("scene to-dat", () => Run(parse.GetValue(files) ?? [], parse.GetValue(cell) ?? string.Empty, parse.GetValue(portal) ?? string.Empty, parse.GetValue(blockSize))));
        return command;
    }

    private static int Run(string[] files, string cell, string portal, uint blockSize)
    {
        OutputPath.Check("--cell", cell);
        OutputPath.Check("--portal", portal);
        OutputPath.CheckDistinct([("--cell", cell), ("--portal", portal)], files);
        if (blockSize is < DatContainer.MinBlockSize or > DatContainer.MaxBlockSize)
        {
            throw new UsageException($"--block-size {blockSize}: expected {DatContainer.MinBlockSize}..{DatContainer.MaxBlockSize}");
        }

        var scenes = files.Select(Read).ToList();
        (int Cell, int Portal) counts;
        try
        {
            counts = SceneContainers.Write(scenes, cell, portal, blockSize);
        }
        catch (ArgumentException e)
        {
            throw new UsageException(e.Message, e);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            throw new OutputPathException($"cannot write the dat files: {e.Message}", e);
        }

        Terminal.Line($"scene to-dat: wrote {cell} ({counts.Cell} objects) and {portal} ({counts.Portal} objects) from {scenes.Count} scene(s), block size {blockSize}");
        return ExitCodes.Ok;
    }

    private static Scene Read(string path)
    {
        if (!File.Exists(path))
        {
            throw new UsageException($"{(path.Length == 0 ? "''" : path)}: no such file");
        }

        string text = File.ReadAllText(path);
        try
        {
            return text.Contains("\"format\"", StringComparison.Ordinal)
                ? CorpusJson.Read(text, path).SceneWalk?.Scene ?? throw new UsageException($"{path}: $.kind: scene to-dat takes scene walks")
                : SceneJson.Read(text, path);
        }
        catch (InputFormatException e)
        {
            throw new UsageException(e.Message, e);
        }
    }
}
