using System.Globalization;
using System.Text;
using AcPhys.Spec.Judging;

namespace AcPhys.Cli.Render;

/// <summary>
/// The picture of a case that is not a walk (a LandDefs input, one query, a parts query) or a walk the implementation
/// could not take: the title, the case on one line, and every judge's verdict, violations in red.
/// </summary>
internal static class VerdictCard
{
    private const int Line = 15;

    /// <summary>Draws the card.</summary>
    /// <param name="run">The case run.</param>
    /// <param name="title">The caption.</param>
    /// <returns>The SVG text.</returns>
    public static string Render(CaseRun run, string title)
    {
        var rows = new List<(string Text, string Style)>();
        rows.AddRange(SvgText.Wrap(title, 110).Select(l => (l, " class=\"title\" font-weight=\"bold\"")));
        var violated = run.Judgement.ViolatedIds;
        string headline = violated.Count > 0 ? "violated: " + string.Join(", ", violated) : "no violation";
        rows.AddRange(SvgText.Wrap(headline, 110).Select(l => (l, $" class=\"headline\" fill=\"{(violated.Count > 0 ? "red" : "#000")}\"")));
        rows.AddRange(SvgText.Wrap(run.Judgement.Case.ToString(), 110).Select(l => (l, " class=\"case\" fill=\"#555\"")));
        foreach (var v in run.Judgement.Verdicts)
        {
            string verdict = v.Outcome is null ? "NOT TESTED" : v.Outcome.Value.Verdict.ToString().ToUpperInvariant();
            string text = $"{verdict,-10} {v.Invariant.Id}" + (v.IsViolation ? ": " + v.Outcome!.Value.Message : string.Empty);
            rows.AddRange(SvgText.Wrap(text, 110).Select(l => (l, v.IsViolation ? " class=\"fail\" fill=\"red\"" : string.Empty)));
        }

        int height = (rows.Count * Line) + 10;
        var sb = new StringBuilder();
        sb.Append(CultureInfo.InvariantCulture, $"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"{height}\" viewBox=\"0 0 800 {height}\" font-family=\"monospace\" font-size=\"11\">\n");
        sb.Append($"<title>{SvgText.Escape(title)}</title>\n<rect x=\"0\" y=\"0\" width=\"800\" height=\"{height}\" fill=\"white\"/>\n");
        int y = 0;
        foreach (var (text, style) in rows)
        {
            y += Line;
            sb.Append(CultureInfo.InvariantCulture, $"<text x=\"4\" y=\"{y}\"{style} xml:space=\"preserve\">{SvgText.Escape(text)}</text>\n");
        }

        sb.Append("</svg>\n");
        return sb.ToString();
    }
}
