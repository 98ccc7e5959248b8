using System.CommandLine;
using AcPhys.Cli.Capture;
using AcPhys.Cli.Impl;
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
        var file = new Argument<string>("file") { Description = "A case file of any kind (walks and scene walks are drawn; other kinds as a card of verdicts), a record folder holding a scene walk, or a capture (a file not starting with '{', or any file with a capture option): its path checked as capture check does." };
        var output = new Option<string>("--output", "-o") { Description = "The SVG file to write (atomically), or - for stdout.", HelpName = "FILE", Required = true };
        var fault = new Option<string>("--fault") { Description = "Run the walk against the reference with this planted fault.", HelpName = "FAULT" };
        var format = new Option<string>("--format") { Description = "A capture: native (default) or acdream, as capture check.", HelpName = "native|acdream" };
        var origin = new Option<string>("--world-origin") { Description = "A capture, --format acdream: the landblock whose south-west corner is the client's world (0, 0).", HelpName = "0xAABB" };
        var radius = new Option<string>("--radius") { Description = "A capture that names no body: the body's radius in metres.", HelpName = "METRES" };
        var pick = new Option<string>("--pick") { Description = "A capture: the pick policy the port declares, retail (default) or current-first.", HelpName = "POLICY" };
        var fidelity = new Option<string>("--fidelity") { Description = "A capture: the documented deviations the port declares (comma-separated).", HelpName = "NAMES" };
        var command = new Command("render", "Draw a stored case as SVG: a walk or a scene walk with the first violating step highlighted (a minimised capture's recorded answers beside the reference's), any other kind as its verdicts; or a capture: its path, cells and block lines, divergent spans in red with the first divergence labelled.")
        {
            file, output, fault, format, origin, radius, pick, fidelity,
        };
        command.SetAction(parse => Guard.Run("render", () =>
        {
            string path = parse.GetValue(file) ?? string.Empty, o = parse.GetValue(output)!;
            string?[] capture = [parse.GetValue(format), parse.GetValue(origin), parse.GetValue(radius), parse.GetValue(pick), parse.GetValue(fidelity)];
            if (!CaptureRender.IsCapture(path, capture.Any(c => c is not null)))
            {
                return Run(path, o, parse.GetValue(fault));
            }

            if (parse.GetValue(fault) is not null)
            {
                throw new UsageException("--fault applies to a case file; a capture is the port's own record");
            }

            OutputPath.Check("-o", o);
            OutputPath.CheckDistinct([("-o", o)], [path]);
            var settings = CaptureSettings.Parse(path, capture[0], capture[1], capture[2], capture[3], capture[4], ImplementationChoice.Reference, quiet: true, minimise: null);
            var (summary, exit) = CaptureRender.Run(settings, o);
            Said(o, summary);
            return exit;
        }));
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
