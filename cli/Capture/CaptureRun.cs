using System.Globalization;
using AcPhys.Cli.Impl;
using AcPhys.Cli.Verify;
using AcPhys.Contract;
using AcPhys.Formats.Capture;
using AcPhys.Formats.Cases;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Capture;

namespace AcPhys.Cli.Capture;

/// <summary>Runs <c>acphys capture check</c>: reads, judges, prints, minimises (docs/cli.md).</summary>
internal static class CaptureRun
{
    /// <summary>How many spans of one finding are listed (the rest are counted).</summary>
    public const int SpansShown = 5;

    /// <summary>Runs the check.</summary>
    /// <param name="s">The settings.</param>
    /// <returns>The exit code.</returns>
    public static int Run(CaptureSettings s)
    {
        ICellPhysics? port = null;
        IDisposable? owned = null;
        if (s.Implementation.IsExternal)
        {
            (port, owned) = s.Implementation.Open(line => Console.Error.WriteLine("[impl] " + line));
        }

        using var world = s.Dats is { } d ? Commands.SceneFromDat.OpenWorld(d.Cell, d.Portal, "--cell-dat", "--portal-dat") : null;
        using (owned)
        using (var reader = CaptureReaders.Open(s.File, s.Format, s.Options))
        {
            if (s.Format == CaptureFormat.Native && reader.Header.Body.Count > 0 && s.Options.Radius is not null)
            {
                throw new UsageException($"{s.File}: the capture names its body (# radius / # body); --radius is for a log that does not");
            }

            var pick = port?.Pick ?? s.Pick;
            var outdoor = port?.Outdoor ?? s.Fidelity.Outdoor;
            var scenes = world is null ? null : new DatScenes(world);
            var checker = new CaptureChecker(scenes is null ? CaptureChecker.OutdoorOnly(pick, outdoor) : CaptureChecker.WithDats(scenes, pick, s.Fidelity.Indoor, outdoor), port);
            CaptureReport report = null!;
            long length = Math.Max(reader.Length, 1);
            ProgressBars.Run($"capture check {Path.GetFileName(s.File)}", 1000, advance =>
            {
                int shown = 0;
                report = checker.Check(reader, at =>
                {
                    int now = (int)Math.Min(1000, at * 1000 / length);
                    for (; shown < now; shown++)
                    {
                        advance(string.Create(CultureInfo.InvariantCulture, $"{at / 1e6:0.0} MB"));
                    }
                });
            }, enabled: !s.Quiet);
            string? dat = world is null ? null : string.Create(CultureInfo.InvariantCulture, $"  dat world: {world.Cell.Name} ({world.Cell.Count:N0} objects), {world.Portal.Name} ({world.Portal.Count:N0} objects); {scenes!.Extracted} landblock scene{(scenes.Extracted == 1 ? string.Empty : "s")} extracted{(scenes.Refused.Count > 0 ? $", {scenes.Refused.Count} refused ({string.Join("; ", scenes.Refused.Take(3).Select(r => $"{r.Key}: {r.Value}"))})" : string.Empty)}");
            Print(s, reader, report, port, dat);
            if (report.Spans.Count > 0 && s.Minimise is not null)
            {
                Minimise(s, report, pick, outdoor);
            }

            if (report.Divergent > 0)
            {
                Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"capture: {report.Divergent:N0} of {report.Judged:N0} judged frames diverge from the reference ({report.Findings.Count} root cause{(report.Findings.Count == 1 ? string.Empty : "s")})"));
                return ExitCodes.Violated;
            }

            if (report.Judged == 0)
            {
                Terminal.Line("capture: no frame was judged (see the reasons above): nothing is shown to agree");
                return ExitCodes.TooFewTested;
            }

            Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"capture: all {report.Judged:N0} judged frames agree with the reference"));
            return ExitCodes.Ok;
        }
    }

    private static void Print(CaptureSettings s, ICaptureReader reader, CaptureReport r, ICellPhysics? port, string? dat)
    {
        var h = reader.Header;
        string body = h.Body.Count == 0 ? "no body named: the cell is judged, not the candidates"
            : h.Body.Count == 1 && h.Body[0].Offset == default ? $"body r={FloatText.Format(h.Body[0].Radius)}" : $"body of {h.Body.Count} spheres";
        string against = port is null ? $"the log against the reference (pick {PickNames.Of(s.Pick)}{Words(s)})" : $"{port.Name} asked again at every frame (pick {PickNames.Of(port.Pick)})";
        Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"capture {s.File} ({(s.Format == CaptureFormat.Acdream ? "acdream log" : "native")}, {(h.Frame == CaptureFrameKind.World ? "world" : "block")} frame, {body}): {against}"));
        Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"  frames read {r.Read:N0}, judged {r.Judged:N0}, not judged {r.NotJudgedTotal:N0}, divergent {r.Divergent:N0}; lines {reader.Lines:N0} ({r.Ignored:N0} ignored: comments, blank{(s.Format == CaptureFormat.Acdream ? ", other log lines" : string.Empty)})"));
        foreach (var (reason, count) in r.NotJudged)
        {
            Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"  not judged {count,10:N0}  {reason.Id}: {reason.Text}"));
        }

        if (dat is not null)
        {
            Terminal.Line(dat);
        }

        var findings = r.Findings;
        if (findings.Count == 0)
        {
            return;
        }

        Terminal.Line();
        Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"findings: {findings.Count} root cause{(findings.Count == 1 ? string.Empty : "s")} over {r.Spans.Count:N0} divergent span{(r.Spans.Count == 1 ? string.Empty : "s")}{(r.SpansNotKept > 0 ? $" (and {r.SpansNotKept:N0} more spans counted, not kept)" : string.Empty)}"));
        int n = 0;
        foreach (var f in findings)
        {
            Terminal.Line($"  F{++n} [{f.Cause}] {f.Text}");
            foreach (var span in f.Spans.Take(s.Quiet ? 1 : SpansShown))
            {
                Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"     frames {span.First.Number}–{span.LastNumber} (line {span.First.Line}): {span.Describe()}"));
            }

            if (f.Spans.Count > (s.Quiet ? 1 : SpansShown))
            {
                Terminal.Line(string.Create(CultureInfo.InvariantCulture, $"     and {f.Spans.Count - (s.Quiet ? 1 : SpansShown):N0} more span{(f.Spans.Count - (s.Quiet ? 1 : SpansShown) == 1 ? string.Empty : "s")}"));
            }
        }

        Terminal.Line();
        Terminal.Line($"first divergence: frame {r.FirstDivergence}");
    }

    private static void Minimise(CaptureSettings s, CaptureReport r, AcPhys.Core.PickPolicy pick, AcPhys.Core.OutdoorFidelity outdoor)
    {
        var minimiser = new CaptureMinimiser(pick, outdoor, s.Implementation.IsExternal ? null : s.Mode());
        string program = ReplayLine.Program;
        string again = s.Implementation.IsExternal ? string.Join(' ', s.Implementation.Words().Select(ReplayLine.Quote)) : "--impl-cmd 'YOUR PORT'";
        int n = 0;
        Terminal.Line();
        var written = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (var f in r.Findings)
        {
            n++;
            var spans = f.Spans.Where(x => x.Window.Count > 0).ToList();
            if (spans.Count == 0)
            {
                Terminal.Line($"minimised F{n}: not written (no frame of the finding records a cell a walk can replay)");
                continue;
            }

            foreach (var span in spans)
            {
                // Every kept span of the finding (the first CaptureReport.MinimisedSpans of its cause), each its own walk.
                string label = spans.Count == 1 ? $"F{n}" : string.Create(CultureInfo.InvariantCulture, $"F{n} frame {span.First.Number}");
                if (IsIndoor(span))
                {
                    Terminal.Line($"minimised {label}: not written (an indoor finding: a minimised scene walk is not written yet; capture check --cell-dat/--portal-dat shows it at frame {span.First.Number})");
                    continue;
                }

                var least = minimiser.Minimise(span, s.File);
                if (least is null)
                {
                    Terminal.Line($"minimised {label}: not written (no frame of the span records a cell a walk can replay)");
                    continue;
                }

                string json = CorpusJson.Write(least.Entry with { Title = "-" });
                if (written.TryGetValue(json, out string? same))
                {
                    Terminal.Line($"minimised {label}: the same walk as {same}");
                    continue;
                }

                string path = Path.Combine(s.Minimise!, $"capture-F{n}-{f.Cause}-frame{span.First.Number}.json");
                OutputPath.Write(path, CorpusJson.Write(least.Entry));
                written[json] = path;
                Terminal.Line($"minimised {label}: {least.Frames} frame{(least.Frames == 1 ? string.Empty : "s")} -> {path} (its replay violates {string.Join(", ", least.Violated)})");
                Terminal.Line($"  {program} replay {ReplayLine.Quote(path)}");
                Terminal.Line($"  {program} replay {ReplayLine.Quote(path)} {again}");
            }
        }

        Terminal.Line();
    }

    // A span judged in a scene (an env cell on either side, or the reference entering a building): the minimiser walks open land.
    private static bool IsIndoor(DivergentSpan span) =>
        span.ReferenceCell.IsIndoorByLowWord || span.LastReference.IsIndoorByLowWord || span.Window.Any(w => w.Cell.IsIndoorByLowWord || w.Before.IsIndoorByLowWord);

    private static string Words(CaptureSettings s) =>
        ReferenceChoice.FidelityWords(s.Fidelity) is { Count: > 0 } w ? ", fidelity " + string.Join(',', w) : string.Empty;
}
