using System.Globalization;
using System.Text;
using AcPhys.Formats.Cases;
using AcPhys.Spec.Invariants;
using AcPhys.Spec.Judging;

namespace AcPhys.Cli.Render;

/// <summary>
/// Draws a checked walk as SVG: the 24 m cell grid, landblock lines with their ids, the path of sphere 0, the spheres
/// at each step, the containing cell at each step, and the first violating step in red. World metres, north up.
/// </summary>
internal static class WalkSvg
{
    private const double Scale = 8; // pixels per metre at most; shrunk for large walks
    private const double MaxPixels = 1400;
    private const double MaxSpan = 70_000; // metres: more than the whole landscape
    private const double MinPixels = 720;
    private const double HeaderLine = 16;
    private const double LegendLine = 14;

    /// <summary>Renders the SVG document.</summary>
    /// <param name="walk">The walk.</param>
    /// <param name="check">Its trace and violations.</param>
    /// <param name="title">A caption (wrapped, never cut).</param>
    /// <param name="fileInvariant">The invariant the file says found the walk, or null; named in the header when this run does not break it.</param>
    /// <param name="reference">For a walk of recorded answers (a minimised capture): the reference's run, whose containing cell is drawn (dashed green) at every step where it differs from the recorded one; else null.</param>
    /// <returns>The SVG text.</returns>
    public static string Render(Walk walk, CaseRun check, string title, string? fileInvariant = null, CaseRun? reference = null)
    {
        var o = walk.Body.Count > 0 ? walk.Body[0].Offset : default;
        var points = check.Trace.Select(s => (X: s.WorldX + o.X, Y: s.WorldY + o.Y)).ToList();
        double reach = walk.Body.Select(b => Math.Max(Math.Abs(b.Offset.X), Math.Abs(b.Offset.Y)) + b.Radius).DefaultIfEmpty(0).Max();
        double minX = Math.Floor((points.Min(p => p.X) - reach - 36) / 24) * 24, maxX = Math.Ceiling((points.Max(p => p.X) + reach + 36) / 24) * 24;
        double minY = Math.Floor((points.Min(p => p.Y) - reach - 36) / 24) * 24, maxY = Math.Ceiling((points.Max(p => p.Y) + reach + 36) / 24) * 24;
        double span = Math.Max(maxX - minX, maxY - minY);
        if (!double.IsFinite(span) || span > MaxSpan)
        {
            // The grid is drawn cell by cell: a walk across more than the world cannot be drawn (and is not a world walk).
            throw new UsageException(string.Create(CultureInfo.InvariantCulture, $"render draws walks up to {MaxSpan:0} m across (the world is smaller); this one spans {span:G4} m"));
        }

        double scale = Math.Clamp(MinPixels / (maxX - minX), 1e-3, Math.Min(Scale, MaxPixels / span));
        double width = Math.Max((maxX - minX) * scale, MinPixels), height = (maxY - minY) * scale;
        int legendRows = Math.Min(check.Trace.Count, 16) + 1;
        double legend = (legendRows * LegendLine) + 10;
        double Px(double x) => (x - minX) * scale;
        double Py(double y) => (maxY - y) * scale;
        string F(double v) => v.ToString("0.###", CultureInfo.InvariantCulture);

        // header: the title, then every broken invariant with its first step, both wrapped to the picture's width (issue 19).
        int chars = (int)(width / 7);
        int? bad = check.FirstViolatingStep;
        var titleLines = SvgText.Wrap(title, chars);
        var headlineLines = SvgText.Wrap(WalkHeadline.For(check.Trace.Count - 1, check.PerStep, fileInvariant), chars);
        string key = "green: containing cell per step; red outline: the violating step's containing cell; dashed: the cell under its centre";
        var keyLines = SvgText.Wrap(reference is null ? key : key.Replace("green: containing", "green: the port's recorded containing", StringComparison.Ordinal) + "; dashed green: the reference's cell where it differs", chars);
        double header = ((titleLines.Count + headlineLines.Count + keyLines.Count) * HeaderLine) + 6;

        var sb = new StringBuilder();
        sb.Append($"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{F(width)}\" height=\"{F(header + height + legend)}\" viewBox=\"0 {F(-header)} {F(width)} {F(header + height + legend)}\" font-family=\"monospace\" font-size=\"11\">\n");
        sb.Append($"<title>{SvgText.Escape(title)}</title>\n<rect x=\"0\" y=\"{F(-header)}\" width=\"{F(width)}\" height=\"{F(header + height + legend)}\" fill=\"white\"/>\n");
        double hy = -header;
        foreach (var (lines, style) in new[] { (titleLines, " class=\"title\" font-weight=\"bold\""), (headlineLines, $" class=\"headline\" fill=\"{(bad is null ? "#000" : "red")}\""), (keyLines, " fill=\"#555\"") })
        {
            foreach (string line in lines)
            {
                hy += HeaderLine;
                sb.Append($"<text x=\"4\" y=\"{F(hy)}\"{style} xml:space=\"preserve\">{SvgText.Escape(line)}</text>\n");
            }
        }

        // Containing cell of every step (drawn first, under the grid); the violating step's expected cell in red.
        foreach (var step in check.Trace)
        {
            if (!step.Containing.IsNone && step.Containing.IsLand)
            {
                var (gx, gy) = Oracle.LcoordOf(step.Containing);
                bool isBad = step.Index == bad;
                sb.Append($"<rect x=\"{F(Px(24.0 * gx))}\" y=\"{F(Py(24.0 * (gy + 1)))}\" width=\"{F(24 * scale)}\" height=\"{F(24 * scale)}\" fill=\"#bfe0bf\" fill-opacity=\"0.45\" stroke=\"{(isBad ? "red" : "none")}\" stroke-width=\"3\"/>\n");
            }
        }

        foreach (var step in check.Trace)
        {
            if (reference is not null && step.Index < reference.Trace.Count && reference.Trace[step.Index].Containing is { IsNone: false, IsLand: true } r && r != step.Containing)
            {
                var (gx, gy) = Oracle.LcoordOf(r);
                sb.Append($"<rect class=\"reference-cell\" x=\"{F(Px(24.0 * gx) + 3)}\" y=\"{F(Py(24.0 * (gy + 1)) + 3)}\" width=\"{F((24 * scale) - 6)}\" height=\"{F((24 * scale) - 6)}\" fill=\"none\" stroke=\"#2e8b57\" stroke-width=\"3\" stroke-dasharray=\"2 3\"/>\n");
            }
        }

        if (bad is int at)
        {
            var p = points[at];
            double gx = Math.Floor(p.X / 24), gy = Math.Floor(p.Y / 24);
            sb.Append($"<rect x=\"{F(Px(24.0 * gx))}\" y=\"{F(Py(24.0 * (gy + 1)))}\" width=\"{F(24 * scale)}\" height=\"{F(24 * scale)}\" fill=\"none\" stroke=\"red\" stroke-width=\"3\" stroke-dasharray=\"6 3\"/>\n");
        }

        for (double x = minX; x <= maxX; x += 24)
        {
            bool block = x % 192 == 0;
            sb.Append($"<line x1=\"{F(Px(x))}\" y1=\"0\" x2=\"{F(Px(x))}\" y2=\"{F(height)}\" stroke=\"{(block ? "#222" : "#ccc")}\" stroke-width=\"{(block ? 2 : 1)}\"/>\n");
        }

        for (double y = minY; y <= maxY; y += 24)
        {
            bool block = y % 192 == 0;
            sb.Append($"<line x1=\"0\" y1=\"{F(Py(y))}\" x2=\"{F(width)}\" y2=\"{F(Py(y))}\" stroke=\"{(block ? "#222" : "#ccc")}\" stroke-width=\"{(block ? 2 : 1)}\"/>\n");
        }

        // Landblock ids at the south-west corner of every block in view.
        BlockLabels.Append(sb, minX, maxX, minY, maxY, Px, Py, height);

        sb.Append("<polyline fill=\"none\" stroke=\"#1f5fbf\" stroke-width=\"2\" points=\"")
          .Append(string.Join(' ', points.Select(p => $"{F(Px(p.X))},{F(Py(p.Y))}"))).Append("\"/>\n");
        foreach (var step in check.Trace)
        {
            bool isBad = step.Index == bad;
            foreach (var sphere in walk.Body)
            {
                double x = step.WorldX + sphere.Offset.X, y = step.WorldY + sphere.Offset.Y;
                sb.Append($"<circle cx=\"{F(Px(x))}\" cy=\"{F(Py(y))}\" r=\"{F(Math.Max(sphere.Radius * scale, 2))}\" fill=\"{(isBad ? "red" : "#1f5fbf")}\" fill-opacity=\"0.18\" stroke=\"{(isBad ? "red" : "#1f5fbf")}\"/>\n");
            }

            var p = points[step.Index];
            sb.Append($"<text x=\"{F(Px(p.X) + 5)}\" y=\"{F(Py(p.Y) + 14 + (12 * (step.Index % 3)))}\" fill=\"{(isBad ? "red" : "#000")}\">{step.Index}</text>\n");
        }

        // Legend: one line per step (the first 16).
        double ly = height + LegendLine + 4;
        string refHead = reference is null ? string.Empty : "reference   ";
        sb.Append($"<text x=\"4\" y=\"{F(ly)}\" font-weight=\"bold\" xml:space=\"preserve\">step  frame       containing  current     {refHead}violations</text>\n");
        foreach (var step in check.Trace.Take(16))
        {
            ly += LegendLine;
            string line = $"{step.Index,4}  {step.Frame,-10}  {step.Containing,-10}  {step.Current,-10}  {ReferenceColumn(reference, step.Index)}{string.Join(", ", check.PerStep[step.Index].Select(v => v.InvariantId).Distinct())}";
            sb.Append($"<text x=\"4\" y=\"{F(ly)}\" xml:space=\"preserve\" fill=\"{(step.Index == bad ? "red" : "#000")}\">{SvgText.Escape(line)}</text>\n");
        }

        sb.Append("</svg>\n");
        return sb.ToString();
    }

    // The reference's containing cell at a step of a recorded walk ("same" where it agrees), or nothing for a plain walk.
    private static string ReferenceColumn(CaseRun? reference, int index) => reference is null ? string.Empty
        : index >= reference.Trace.Count ? $"{"-",-10}  "
        : $"{reference.Trace[index].Containing.ToString(),-10}  ";
}
