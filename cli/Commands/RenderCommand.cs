using System.CommandLine;
using AcPhys.Cli.Render;
using AcPhys.Cli.Replay;
using AcPhys.Spec.Adapters;
using AcPhys.Spec.Faults;

namespace AcPhys.Cli.Commands;

/// <summary>
/// The <c>render</c> verb: draws a walk or a scene walk as SVG (grid, block lines and ids, path, containing cells, the
/// violating step; for a scene walk also env cell outlines, portals, buildings and unloaded blocks).
/// </summary>
internal static class RenderCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var file = new Argument<string>("file") { Description = "A walk file (kind \"walk\" or \"scene-walk\"), or a record folder holding a scene walk." };
        var output = new Option<string>("--output", "-o") { Description = "The SVG file to write (atomically), or - for stdout.", HelpName = "FILE", Required = true };
        var fault = new Option<string>("--fault") { Description = "Run the walk against the reference with this planted fault.", HelpName = "FAULT" };
        var command = new Command("render", "Draw a walk or a scene walk as SVG, with the first violating step highlighted.") { file, output, fault };
        command.SetAction(parse => Guard.Run("render", () => Run(parse.GetValue(file) ?? string.Empty, parse.GetValue(output)!, parse.GetValue(fault))));
        return command;
    }

    private static int Run(string path, string output, string? faultId)
    {
        OutputPath.Check("-o", output);
        OutputPath.CheckDistinct([("-o", output)], [path]);
        if (!CaseFiles.Exists(path))
        {
            throw new UsageException($"{(path.Length == 0 ? "''" : path)}: no such file or record folder");
        }

        var entry = CaseFiles.Read(path);
        if (entry.Walk is null && entry.SceneWalk is null)
        {
            throw new UsageException($"{path}: $.kind: render draws walks and scene walks; this file is kind \"{entry.Kind}\"");
        }

        ICellPhysics impl = ReferenceAdapter.Instance;
        if (faultId is not null)
        {
            var fault = PlantedFaults.Find(faultId) ?? throw new UsageException($"unknown fault '{faultId}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
            impl = PlantedFaults.Create(fault.Id);
        }

        if (entry.SceneWalk is { } sw)
        {
            var sceneCheck = SceneWalkCheck.Run(impl, sw);
            OutputPath.Write(output, SceneSvg.Render(sw, sceneCheck, $"{entry.Title} — {impl.Name}"));
            Said(output, $"render: wrote {output} ({sceneCheck.Trace.Count - 1} steps, {sw.Scene.Cells.Count} env cells, {sw.Scene.PortalCount} portals, "
                + $"{(sceneCheck.FirstViolatingStep is int f ? $"first violation at step {f}" : "no violation")})");
            return ExitCodes.Ok;
        }

        var check = WalkReplay.Check(impl, entry.Walk!);
        OutputPath.Write(output, WalkSvg.Render(entry.Walk!, check, $"{entry.Title} — {impl.Name}", entry.Invariant));
        Said(output, $"render: wrote {output} ({check.Trace.Count - 1} steps, {(check.FirstViolatingStep is int s ? $"first violation at step {s}" : "no violation")})");
        return ExitCodes.Ok;
    }

    // The summary line goes to stderr when the picture itself went to stdout.
    private static void Said(string output, string line)
    {
        if (output == OutputPath.Stdout)
        {
            Console.Error.WriteLine(line);
        }
        else
        {
            Terminal.Line(line);
        }
    }
}
