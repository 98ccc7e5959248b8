using System.Globalization;
using System.Text;
using AcPhys.Cli.Capture;
using AcPhys.Core;
using AcPhys.Spec.Capture;
using AcPhys.Spec.Invariants;

namespace AcPhys.Cli.Render;

/// <summary>
/// Draws a checked capture as SVG (WalkSvg's style, world metres, north up): the decimated path of the centre, blue
/// where the frames agree, red (class <c>span</c>) over divergent spans with each span's first frame marked and the first
/// divergence labelled, light grey where frames were not judged; the 24 m cell grid (only when the path covers at most
/// <see cref="GridBlocks"/> blocks across) and 192 m block lines; for each finding the port's cell (red) and the
/// reference's (dashed green) at its first frame; the findings as a legend.
/// </summary>
internal static class CaptureSvg
{
    /// <summary>Most blocks across for which the 24 m cell lines are drawn; a wider path gets block lines only.</summary>
    public const int GridBlocks = 4;

    private const double Scale = 8;
    private const double MaxPixels = 1400;
    private const double MinPixels = 720;
    private const double Line = 16;
    private const string Agree = "#1f5fbf", Diverge = "red", Skipped = "#bbbbbb";

    /// <summary>Renders the SVG document.</summary>
    /// <param name="path">The decimated path (at least one point).</param>
    /// <param name="report">The check's report.</param>
    /// <param name="title">A caption (wrapped).</param>
    /// <returns>The SVG text.</returns>
    public static string Render(CapturePath path, CaptureReport report, string title)
    {
        var pts = path.Points;
        double minX = Math.Floor((pts.Min(p => p.X) - 12) / 24) * 24, maxX = Math.Ceiling((pts.Max(p => p.X) + 12) / 24) * 24;
        double minY = Math.Floor((pts.Min(p => p.Y) - 12) / 24) * 24, maxY = Math.Ceiling((pts.Max(p => p.Y) + 12) / 24) * 24;
        double span = Math.Max(maxX - minX, maxY - minY);
        double scale = Math.Min(Scale, MaxPixels / span);
        double width = Math.Max((maxX - minX) * scale, MinPixels), height = (maxY - minY) * scale;
        double Px(double x) => (x - minX) * scale;
        double Py(double y) => (maxY - y) * scale;
        string F(double v) => SvgText.Num(v);

        int chars = (int)(width / 7);
        var findings = report.Findings;
        string counts = string.Create(CultureInfo.InvariantCulture, $"frames read {report.Read:N0}, judged {report.Judged:N0}, not judged {report.NotJudgedTotal:N0}, divergent {report.Divergent:N0}; drawn {pts.Count:N0} points");
        string verdict = report.FirstDivergence is long first ? $"first divergence: frame {first}" : "no divergence: every judged frame agrees with the reference";
        var header = new List<(string Text, string Style)>();
        header.AddRange(SvgText.Wrap(title, chars).Select(l => (l, " class=\"title\" font-weight=\"bold\"")));
        header.AddRange(SvgText.Wrap(counts, chars).Select(l => (l, string.Empty)));
        header.Add((verdict, $" class=\"headline\" fill=\"{(report.FirstDivergence is null ? "#000" : "red")}\""));
        header.AddRange(SvgText.Wrap("blue: agreeing frames; red: divergent spans (dot: a span's first frame); grey: not judged; red box: the port's cell, dashed green: the reference's, at each finding's first frame", chars).Select(l => (l, " fill=\"#555\"")));
        var legend = new List<string>();
        int n = 0;
        foreach (var f in findings)
        {
            legend.AddRange(SvgText.Wrap($"F{++n} [{f.Cause}] {f.Text}", chars));
            foreach (var s in f.Spans.Take(CaptureRun.SpansShown))
            {
                legend.AddRange(SvgText.Wrap(string.Create(CultureInfo.InvariantCulture, $"   frames {s.First.Number}–{s.LastNumber} (line {s.First.Line}): {s.Describe()}"), chars));
            }
        }

        double top = (header.Count * Line) + 6, bottom = (legend.Count * Line) + 10;
        var sb = new StringBuilder();
        sb.Append($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{F(width)}\" height=\"{F(top + height + bottom)}\" viewBox=\"0 {F(-top)} {F(width)} {F(top + height + bottom)}\" font-family=\"monospace\" font-size=\"11\">\n");
        sb.Append($"<title>{SvgText.Escape(title)}</title>\n<rect x=\"0\" y=\"{F(-top)}\" width=\"{F(width)}\" height=\"{F(top + height + bottom)}\" fill=\"white\"/>\n");
        double hy = -top;
        foreach (var (text, style) in header)
        {
            hy += Line;
            sb.Append($"<text x=\"4\" y=\"{F(hy)}\"{style} xml:space=\"preserve\">{SvgText.Escape(text)}</text>\n");
        }

        // The port's cell and the reference's at each finding's first frame (land cells only).
        foreach (var f in findings)
        {
            var s = f.Spans[0];
            Cell(sb, s.PortCell, "red", string.Empty, 0);
            Cell(sb, s.ReferenceCell, "#2e8b57", " stroke-dasharray=\"6 3\"", 3);
        }

        Grid(sb, minX, maxX, minY, maxY, Px, Py, width, height);
        Polylines(sb, pts, Px, Py);
        foreach (var p in pts.Where(p => p.Kind == VerdictKind.NotJudged))
        {
            sb.Append($"<circle class=\"not-judged\" cx=\"{F(Px(p.X))}\" cy=\"{F(Py(p.Y))}\" r=\"1.5\" fill=\"{Skipped}\"/>\n");
        }

        foreach (var s in report.Spans)
        {
            sb.Append($"<circle class=\"span-start\" cx=\"{F(Px(s.First.WorldX))}\" cy=\"{F(Py(s.First.WorldY))}\" r=\"4\" fill=\"{Diverge}\"/>\n");
        }

        n = 0;
        foreach (var f in findings)
        {
            var s = f.Spans[0];
            string label = (report.FirstDivergence is long fd && s.First.Number == fd ? $"first divergence: frame {fd}; " : string.Empty) + $"F{++n} [{f.Cause}]";
            sb.Append($"<text class=\"span-label\" x=\"{F(Px(s.First.WorldX) + 7)}\" y=\"{F(Py(s.First.WorldY) + 16 + (12 * ((n - 1) % 4)))}\" fill=\"{Diverge}\">{SvgText.Escape(label)}</text>\n");
        }

        if (report.FirstDivergence is long firstFrame && !findings.SelectMany(f => f.Spans.Take(1)).Any(s => s.First.Number == firstFrame))
        {
            var s = report.Spans[0];
            sb.Append($"<text class=\"span-label\" x=\"{F(Px(s.First.WorldX) + 7)}\" y=\"{F(Py(s.First.WorldY) + 14)}\" fill=\"{Diverge}\">first divergence: frame {firstFrame}</text>\n");
        }

        double ly = height + 4;
        foreach (string line in legend)
        {
            ly += Line;
            sb.Append($"<text x=\"4\" y=\"{F(ly)}\" xml:space=\"preserve\" fill=\"{(line.StartsWith('F') ? Diverge : "#000")}\">{SvgText.Escape(line)}</text>\n");
        }

        sb.Append("</svg>\n");
        return sb.ToString();

        void Cell(StringBuilder b, CellId id, string colour, string dash, double inset)
        {
            if (id.IsNone || !id.IsLand)
            {
                return;
            }

            var (gx, gy) = Oracle.LcoordOf(id);
            b.Append($"<rect class=\"cell\" x=\"{F(Px(24.0 * gx) + inset)}\" y=\"{F(Py(24.0 * (gy + 1)) + inset)}\" width=\"{F(Math.Max((24 * scale) - (2 * inset), 2))}\" height=\"{F(Math.Max((24 * scale) - (2 * inset), 2))}\" fill=\"{colour}\" fill-opacity=\"0.12\" stroke=\"{colour}\" stroke-width=\"3\"{dash}/>\n");
        }
    }

    // Cell lines when the region is at most GridBlocks blocks across, block lines always, block ids when few.
    private static void Grid(StringBuilder sb, double minX, double maxX, double minY, double maxY, Func<double, double> px, Func<double, double> py, double width, double height)
    {
        bool cells = Math.Max(maxX - minX, maxY - minY) <= GridBlocks * LandDefs.BlockLength;
        double step = cells ? 24 : 192;
        for (double x = Math.Ceiling(minX / step) * step; x <= maxX; x += step)
        {
            bool block = x % 192 == 0;
            sb.Append($"<line x1=\"{SvgText.Num(px(x))}\" y1=\"0\" x2=\"{SvgText.Num(px(x))}\" y2=\"{SvgText.Num(height)}\" stroke=\"{(block ? "#222" : "#ccc")}\" stroke-width=\"{(block ? 2 : 1)}\"/>\n");
        }

        for (double y = Math.Ceiling(minY / step) * step; y <= maxY; y += step)
        {
            bool block = y % 192 == 0;
            sb.Append($"<line x1=\"0\" y1=\"{SvgText.Num(py(y))}\" x2=\"{SvgText.Num(width)}\" y2=\"{SvgText.Num(py(y))}\" stroke=\"{(block ? "#222" : "#ccc")}\" stroke-width=\"{(block ? 2 : 1)}\"/>\n");
        }

        if ((maxX - minX) / 192 * ((maxY - minY) / 192) > 64)
        {
            return;
        }

        BlockLabels.Append(sb, minX, maxX, minY, maxY, px, py, height);
    }

    // One polyline per run of frames of one verdict, each starting at the run before's last point so the path is unbroken.
    private static void Polylines(StringBuilder sb, IReadOnlyList<CapturePoint> pts, Func<double, double> px, Func<double, double> py)
    {
        int i = 0;
        while (i < pts.Count)
        {
            var kind = pts[i].Kind;
            int end = i;
            while (end + 1 < pts.Count && pts[end + 1].Kind == kind)
            {
                end++;
            }

            var (colour, width, cls) = kind switch
            {
                VerdictKind.Diverges => (Diverge, 4, "span"),
                VerdictKind.NotJudged => (Skipped, 2, "not-judged-path"),
                _ => (Agree, 2, "agree"),
            };
            sb.Append($"<polyline class=\"{cls}\" fill=\"none\" stroke=\"{colour}\" stroke-width=\"{width}\" points=\"");
            for (int k = Math.Max(i - 1, 0); k <= end; k++)
            {
                sb.Append(SvgText.Num(px(pts[k].X))).Append(',').Append(SvgText.Num(py(pts[k].Y))).Append(' ');
            }

            sb.Append("\"/>\n");
            i = end + 1;
        }
    }
}
