using System.CommandLine;
using AcPhys.Cli.Capture;
using AcPhys.Cli.Impl;

namespace AcPhys.Cli.Commands;

/// <summary>The <c>capture</c> verb: a port's own recorded session, checked frame by frame and minimised (<c>capture check</c>).</summary>
internal static class CaptureCommand
{
    /// <summary>Builds the command.</summary>
    /// <returns>The command.</returns>
    public static Command Create()
    {
        var file = new Argument<string>("file") { Description = "The capture: native (docs/corpus-format.md, \"Captures\") or an acdream log (--format acdream). Read only, streamed." };
        var format = new Option<string>("--format") { Description = "native (default: frame, cell, x, y, z [, radius] [, candidates], tab-separated) or acdream ([cell-transit] / [cellset-build] probe lines).", HelpName = "native|acdream" };
        var origin = new Option<string>("--world-origin") { Description = "--format acdream: the landblock whose south-west corner is the client's world (0, 0).", HelpName = "0xAABB" };
        var radius = new Option<string>("--radius") { Description = "The body's radius in metres, when the capture names none (an acdream log never does); without one only the cell is judged.", HelpName = "METRES" };
        var pick = new Option<string>("--pick") { Description = "The pick policy the port declares: retail (default) or current-first.", HelpName = "POLICY" };
        var fidelity = new Option<string>("--fidelity") { Description = "The documented deviations the port declares (comma-separated, as verify).", HelpName = "NAMES" };
        var quiet = new Option<bool>("--quiet", "-q") { Description = "No progress bar; only the counts, the findings and the verdict (for CI logs)." };
        var minimise = new Option<string>("--minimise") { Description = "Shrink every finding to the shortest walk that still shows it and write each as a walk case file (with the port's recorded answers) into this folder.", HelpName = "DIR" };
        var cellDat = new Option<string>("--cell-dat") { Description = "Your cell database (client_cell_1.dat): env-cell frames and frames by a building are judged in the scene it gives (docs/ports.md, \"Your own sessions\"). Needs --portal-dat.", HelpName = "FILE" };
        var portalDat = new Option<string>("--portal-dat") { Description = "The portal database (client_portal.dat) beside --cell-dat.", HelpName = "FILE" };
        var implOptions = new ImplementationOptions();
        var check = new Command("check", "Judge every frame of a capture against the reference in the declared mode, threading the port's cell as a walk does; report divergent spans by root cause and the first divergent frame (exit 0 agree, 1 a divergence, 2 bad input, 4 no frame judged).")
        {
            file, format, origin, radius, pick, fidelity, quiet, minimise, cellDat, portalDat,
        };
        foreach (var option in implOptions.All)
        {
            check.Options.Add(option);
        }

        check.SetAction(parse => Guard.Run("capture check", () => CaptureRun.Run(CaptureSettings.Parse(
            parse.GetValue(file) ?? string.Empty,
            parse.GetValue(format),
            parse.GetValue(origin),
            parse.GetValue(radius),
            parse.GetValue(pick),
            parse.GetValue(fidelity),
            implOptions.Read(parse),
            parse.GetValue(quiet),
            parse.GetValue(minimise),
            parse.GetValue(cellDat),
            parse.GetValue(portalDat)))));
        return new Command("capture", "Your own sessions: check a recorded capture frame by frame and minimise its findings into replayable walks.") { check };
    }
}
