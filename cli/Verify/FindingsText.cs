using AcPhys.Spec.Invariants;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>Prints a run's findings: one block per root cause with the invariants it breaks and its smallest case (issue #18).</summary>
internal static class FindingsText
{
    /// <summary>Writes the findings after the failures, when any invariant failed.</summary>
    /// <param name="results">The run's results.</param>
    public static void Write(IReadOnlyList<InvariantResult> results)
    {
        var findings = Findings.Of(results);
        if (findings.Count == 0)
        {
            return;
        }

        Terminal.Line();
        Console.Out.Write(Plain(findings));
    }

    /// <summary>Renders findings as plain text lines (the terminal block, and the JUnit suite's system-out).</summary>
    /// <param name="findings">The findings.</param>
    /// <returns>The text, one line per row, each ending in a newline.</returns>
    public static string Plain(IReadOnlyList<Finding> findings)
    {
        int failures = findings.Sum(f => f.Failures.Count);
        var text = new System.Text.StringBuilder();
        text.Append($"findings: {findings.Count} failure class{(findings.Count == 1 ? string.Empty : "es")} over {failures} failure{(failures == 1 ? string.Empty : "s")} (failures whose shrunk cases share a class are one finding; each invariant reports up to {CatalogueRunner.MaxClasses} classes)\n");
        int n = 0;
        foreach (var f in findings)
        {
            var (id, v) = f.Example;
            text.Append($"  F{++n} [{f.Cause}] breaks {string.Join(", ", f.Invariants)}\n");
            foreach (string rule in Rules(f))
            {
                text.Append($"     {rule}\n");
            }

            text.Append($"     smallest case ({id}): {Brief(v.CaseText)}\n");
            text.Append($"     {Brief(v.Message)}\n");
        }

        return text.ToString();
    }

    /// <summary>Appends the findings to a markdown summary.</summary>
    /// <param name="md">The summary.</param>
    /// <param name="results">The run's results.</param>
    public static void Append(System.Text.StringBuilder md, IReadOnlyList<InvariantResult> results)
    {
        var findings = Findings.Of(results);
        if (findings.Count == 0)
        {
            return;
        }

        md.Append("\n### Findings (one per failure class)\n\n| # | class | invariants it breaks | smallest case |\n|---:|---|---|---|\n");
        int n = 0;
        foreach (var f in findings)
        {
            var (_, v) = f.Example;
            md.Append($"| F{++n} | `{f.Cause}` | {string.Join(", ", f.Invariants.Select(i => $"`{i}`"))} | `{Brief(v.CaseText).Replace("|", "\\|", StringComparison.Ordinal)}` |\n");
        }
    }

    /// <summary>Returns, per invariant a finding breaks, the rule it states and where the facts say so (issue #29: a port
    /// maintainer reads which retail rule the port departs from, and whether it is a retail statement or a hardening rule).</summary>
    /// <param name="f">The finding.</param>
    /// <returns>One line per invariant.</returns>
    public static IEnumerable<string> Rules(Finding f) =>
        f.Invariants.Select(InvariantCatalogue.Find).OfType<Invariant>().Select(i =>
            $"{i.Id} ({(i.Scope is { } scope ? InvariantScope.Name(scope) : "rule")}, {i.Source}): {Brief(i.Statement)}");

    private static string Brief(string text)
    {
        string one = text.ReplaceLineEndings(" ");
        return one.Length <= 200 ? one : one[..199] + "…";
    }
}
