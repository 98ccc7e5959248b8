using System.Globalization;
using System.Text;
using AcPhys.Core;
using AcPhys.Spec.Capture;

namespace AcPhys.Props.Capture;

/// <summary>
/// CAPTURE-MINIMISE-SPANS: every divergent span is minimised, not only the first of its cause — the checker keeps the
/// frames of the first <see cref="CaptureReport.MinimisedSpans"/> spans of each cause (constant memory past them), and
/// each of those minimises to a walk of its own whose replay fails.
/// </summary>
public sealed class CaptureMinimiseSpansTests
{
    [Fact(DisplayName = "CAPTURE-MINIMISE-SPANS: seven one-frame freezes over the A9B4/A9B3 line, each after an agreeing frame: the first five spans keep their frames and each minimises to a failing walk; the last two are only counted")]
    public void EveryKeptSpanMinimises()
    {
        // Frame 2k at y = 0.05 in 0xA9B40031 (agrees), frame 2k + 1 at y = −0.05 still in 0xA9B40031 (the reference: 0xA9B30038).
        var text = new StringBuilder("# frame: block\n# radius: 0.48\n");
        for (int k = 0; k < 7; k++)
        {
            text.Append(CultureInfo.InvariantCulture, $"{2 * k}\t0xA9B40031\t{150 + k:F3}\t0.050\t0.000\n{(2 * k) + 1}\t0xA9B40031\t{150 + k:F3}\t-0.050\t0.000\n");
        }

        var report = CaptureRunner.Check(text.ToString());
        Assert.Equal(7, report.Spans.Count);
        Assert.All(report.Spans, s => Assert.Equal("cell-held-across-block-line", s.Cause));
        Assert.All(report.Spans.Take(CaptureReport.MinimisedSpans), s => Assert.Equal(2, s.Window.Count)); // the last agreed frame and the first divergent one
        Assert.All(report.Spans.Skip(CaptureReport.MinimisedSpans), s => Assert.Empty(s.Window));
        var minimiser = new CaptureMinimiser(PickPolicy.Retail, default, null);
        var walks = report.Spans.Take(CaptureReport.MinimisedSpans).Select(s => minimiser.Minimise(s, "spans.capture")).ToList();
        Assert.All(walks, w => Assert.Contains("NO-BOUNDARY-FREEZE", Assert.IsType<MinimisedCapture>(w).Violated));
        Assert.Equal(CaptureReport.MinimisedSpans, walks.Select(w => w!.Entry.Walk!.Start.X).Distinct().Count()); // each span's own place
    }
}
