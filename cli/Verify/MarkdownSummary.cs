using System.Text;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>
/// Renders a run as markdown fit for a PR comment: a verdict line, the invariant table, and each failure with its
/// minimised case (or walk), seed and replay command; what was not tested is listed with the reason.
/// </summary>
internal static class MarkdownSummary
{
    /// <summary>Renders the markdown.</summary>
    /// <param name="run">The run.</param>
    /// <returns>The text.</returns>
    public static string Render(GateRun run)
    {
        var md = new StringBuilder();
        string verdict = run.Failed > 0 ? $"❌ {run.Failed} invariant{(run.Failed == 1 ? string.Empty : "s")} violated"
            : run.TooFewTested ? $"❌ {Inline(run.TooFewTestedText)}" : "✅ every tested invariant held";
        md.Append("## acphys verify: ").Append(verdict).Append("\n\n");
        md.Append($"Implementation **{Cell(run.ImplName)}**, profile `{run.Settings.Profile.Name}` ");
        md.Append($"({Fmt.Count(run.Settings.Profile.CasesPerInvariant)} generated cases per invariant{(run.Settings.Profile.Exhaustive ? " + exhaustive sweeps" : string.Empty)}), ");
        md.Append($"{run.SeedText}, {Fmt.Seconds(run.Elapsed)}: ");
        md.Append($"{run.Passed} passed, {run.Failed} failed, {run.NotTested} not tested.\n\n");
        if (run.UnknownOps.Count > 0)
        {
            md.Append($"> ⚠️ The implementation announced ops protocol v1 does not know (ignored): {Inline(run.UnknownOpsText)}\n\n");
        }


        md.Append("| Invariant | Scope | Verdict | Cases | Applicable | Time |\n|---|---|---|---:|---:|---:|\n");
        foreach (var r in run.Results)
        {
            string cases = r.Status == ResultStatus.NotTested ? "-" : r.ExhaustiveCases > 0 ? $"{Fmt.Count(r.Cases)} + {Fmt.Count(r.ExhaustiveCases)}" : Fmt.Count(r.Cases);
            string applicable = r.Status == ResultStatus.NotTested ? "-" : Fmt.Percent(r.Applicable, r.Cases);
            md.Append($"| `{r.Invariant.Id}` | {(r.Invariant.Scope is { } scope ? AcPhys.Spec.Invariants.InvariantScope.Name(scope) : "-")} | {Verdict(r.Status)} | {cases} | {applicable} | {Fmt.Seconds(r.Elapsed)} |\n");
        }

        FindingsText.Append(md, run.Results);
        foreach (var r in run.Results.Where(r => r.Status == ResultStatus.Failed))
        {
            var detail = run.Failures.GetValueOrDefault(r.Invariant.Id);
            md.Append($"\n### ❌ `{r.Invariant.Id}`\n\n");
            md.Append(r.Invariant.Statement).Append("\n\n");
            if (r.Violation is { } v)
            {
                bool walk = v.CaseText.Contains('\n', StringComparison.Ordinal) || v.Case is AcPhys.Formats.Cases.AnyCase.OutdoorWalk;
                md.Append(walk ? "Minimised walk:\n\n" : "Minimised case:\n\n");
                Fence(md, v.CaseText);
                md.Append("Message: ").Append(Inline(v.Message)).Append("\n\n");
                if (detail?.WalkSteps is { Count: > 0 } steps)
                {
                    md.Append($"The walk on {Cell(run.ImplName)}:\n\n| step | frame | position (block frame) | containing | cells |\n|---:|---|---|---|---|\n");
                    foreach (var row in steps)
                    {
                        md.Append("| ").Append(string.Join(" | ", row.Select(Cell))).Append(" |\n");
                    }

                    md.Append('\n');
                }
            }

            md.Append($"Seed: `{r.Seed}`\n\nReplay:\n\n");
            Fence(md, detail?.ReplayLine ?? "(not available)", "sh");
            if (detail?.CaseReplay is string caseReplay)
            {
                md.Append($"The shrunk case is also written to `{detail.CaseFile}`:\n\n");
                Fence(md, caseReplay, "sh");
            }
        }

        var notTested = run.Results.Where(r => r.Status == ResultStatus.NotTested).ToArray();
        if (notTested.Length > 0)
        {
            md.Append("\n<details><summary>Not tested (").Append(notTested.Length).Append(")</summary>\n\n");
            foreach (var r in notTested)
            {
                md.Append($"- `{r.Invariant.Id}`: {Inline(r.NotTestedReason ?? "the implementation lacks an operation it needs")}\n");
            }

            md.Append("\n</details>\n");
        }

        return AcPhys.Formats.Values.InputQuote.Escape(md.ToString(), keepLines: true); // no control character of an implementation reaches the PR comment
    }

    private static string Verdict(ResultStatus status) => status switch
    {
        ResultStatus.Passed => "✅ pass",
        ResultStatus.Failed => "❌ **FAIL**",
        _ => "⚪ not tested",
    };

    private static string Cell(string text) => text.Replace("|", "\\|", StringComparison.Ordinal).Replace("*", "\\*", StringComparison.Ordinal);

    private static string Inline(string text) => text.Replace("\n", " ", StringComparison.Ordinal);

    private static void Fence(StringBuilder md, string text, string language = "text")
    {
        string fence = text.Contains("```", StringComparison.Ordinal) ? "~~~~" : "```";
        md.Append(fence).Append(language).Append('\n').Append(text.TrimEnd('\n')).Append('\n').Append(fence).Append("\n\n");
    }
}
