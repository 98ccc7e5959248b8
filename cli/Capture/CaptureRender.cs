using System.Globalization;
using AcPhys.Cli.Render;
using AcPhys.Contract;
using AcPhys.Formats.Capture;
using AcPhys.Spec.Capture;

namespace AcPhys.Cli.Capture;

/// <summary>
/// <c>acphys render CAPTURE</c>: the capture checked as <c>capture check</c> checks it (same settings), streamed once,
/// its decimated path (<see cref="CapturePath"/>) drawn with the report (<see cref="CaptureSvg"/>).
/// </summary>
internal static class CaptureRender
{
    /// <summary>Whether a file is read as a capture rather than a case file: any file when a capture option was given,
    /// else one whose first non-blank character (after a byte-order mark) is not <c>{</c> (a case file is a JSON object).</summary>
    /// <param name="path">The file.</param>
    /// <param name="captureOption">Whether --format / --world-origin / --radius / --pick / --fidelity was given.</param>
    /// <returns>True for a capture.</returns>
    public static bool IsCapture(string path, bool captureOption)
    {
        if (!File.Exists(path))
        {
            return false;
        }

        if (captureOption)
        {
            return true;
        }

        using var stream = File.OpenRead(path);
        Span<byte> head = stackalloc byte[4096];
        int n = stream.Read(head);
        var text = head[..n];
        if (text.StartsWith("\uFEFF"u8))
        {
            text = text[3..];
        }

        foreach (byte b in text)
        {
            if (b is (byte)' ' or (byte)'\t' or (byte)'\r' or (byte)'\n')
            {
                continue;
            }

            return b != (byte)'{';
        }

        return false; // empty or blank: the case reader names what it expected
    }

    /// <summary>Checks and draws a capture.</summary>
    /// <param name="s">The settings (as capture check's; no implementation).</param>
    /// <param name="output">The SVG file, or - for stdout.</param>
    /// <returns>The summary line and the exit code (0 drawn; a divergence is drawn, not an error).</returns>
    public static (string Summary, int Exit) Run(CaptureSettings s, string output)
    {
        using var reader = CaptureReaders.Open(s.File, s.Format, s.Options);
        if (s.Format == CaptureFormat.Native && reader.Header.Body.Count > 0 && s.Options.Radius is not null)
        {
            throw new UsageException($"{s.File}: the capture names its body (# radius / # body); --radius is for a log that does not");
        }

        var checker = new CaptureChecker(CaptureChecker.OutdoorOnly(s.Pick, s.Fidelity.Outdoor));
        var path = new CapturePath();
        var report = checker.Check(reader, observe: (q, v) => path.Add(q.Frame.Number, q.WorldX, q.WorldY, v.Kind));
        path.Finish();
        if (path.Points.Count == 0)
        {
            throw new UsageException($"{s.File}: no frame to draw ({reader.Lines:N0} lines, {reader.Ignored:N0} ignored)");
        }

        string title = $"capture {Path.GetFileName(s.File)} ({(s.Format == CaptureFormat.Acdream ? "acdream log" : "native")}) against the reference (pick {PickNames.Of(s.Pick)})";
        OutputPath.Write(output, CaptureSvg.Render(path, report, title));
        string verdict = report.FirstDivergence is long f
            ? string.Create(CultureInfo.InvariantCulture, $"{report.Divergent:N0} divergent frames, first divergence: frame {f}")
            : "no divergence";
        return (string.Create(CultureInfo.InvariantCulture, $"render: wrote {output} (capture: {report.Read:N0} frames, {path.Points.Count:N0} drawn, {verdict})"), ExitCodes.Ok);
    }
}
