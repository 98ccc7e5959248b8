using System.CommandLine;
using AcPhys.Cli.Render;
using AcPhys.Cli.Replay;
using AcPhys.Contract;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Faults;
using AcPhys.Spec.Judging;

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
        var file = new Argument<string>("file") { Description = "A case file of any kind (walks and scene walks are drawn; other kinds as a card of verdicts), or a record folder holding a scene walk." };
        var output = new Option<string>("--output", "-o") { Description = "The SVG file to write (atomically), or - for stdout.", HelpName = "FILE", Required = true };
        var fault = new Option<string>("--fault") { Description = "Run the walk against the reference with this planted fault.", HelpName = "FAULT" };
        var command = new Command("render", "Draw a stored case as SVG: a walk or a scene walk with the first violating step highlighted, any other kind as its verdicts.") { file, output, fault };
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
        ICellPhysics impl = ReferenceAdapter.Instance;
        if (faultId is not null)
        {
            var fault = PlantedFaults.Find(faultId) ?? throw new UsageException($"unknown fault '{faultId}' (known: {string.Join(", ", PlantedFaults.All.Select(f => f.Id))})");
            impl = PlantedFaults.Create(fault.Id);
        }

        // A minimised capture (field "recorded"): the port's recorded answers are drawn and judged, as replay judges
        // them, with the reference's own answer beside each step where it differs.
        CaseRun? reference = null;
        if (entry is { Walk: { } recordedWalk, Recorded: { } recorded } && faultId is null)
        {
            reference = CaseRun.Of(impl, entry.Item);
            impl = new AcPhys.Spec.Capture.RecordedPhysics(recordedWalk, recorded, impl);
        }

        // Judged as replay judges it (Judges): the picture names what replay reports.
        var run = CaseRun.Of(impl, entry.Item);
        string caption = $"{entry.Title} — {impl.Name}";
        string drawn;
        if (entry.Item is AnyCase.WalkInScene sw && run.Trace.Count > 0)
        {
            OutputPath.Write(output, SceneSvg.Render(sw.Walk, run, caption));
            drawn = $"{run.Trace.Count - 1} steps, {sw.Walk.Scene.Cells.Count} env cells, {sw.Walk.Scene.PortalCount} portals";
        }
        else if (entry.Item is AnyCase.OutdoorWalk w && run.Trace.Count > 0)
        {
            OutputPath.Write(output, WalkSvg.Render(w.Walk, run, caption, entry.Invariant, reference));
            drawn = $"{run.Trace.Count - 1} steps";
        }
        else
        {
            OutputPath.Write(output, VerdictCard.Render(run, caption));
            drawn = $"kind {entry.Kind}: the verdicts";
        }

        var violated = run.Judgement.ViolatedIds;
        string verdict = violated.Count == 0 ? "no violation"
            : (run.Trace.Count > 0 && run.FirstViolatingStep is int f ? $"first violation at step {f}; " : string.Empty) + "violated: " + string.Join(", ", violated);
        Said(output, $"render: wrote {output} ({drawn}, {verdict})");
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
