using System.Text;

namespace AcPhys.Spec.Invariants;

/// <summary>Renders the catalogue as the markdown of docs/invariants.md (a test keeps the file equal to this).</summary>
public static class InvariantDocs
{
    /// <summary>Returns the markdown document.</summary>
    /// <returns>The text, ending in a newline.</returns>
    public static string Markdown()
    {
        var sb = new StringBuilder();
        sb.Append("# Invariants\n\n");
        sb.Append("Generated from the catalogue (`./acphys invariants --markdown`); a test keeps this file equal to it.\n");
        sb.Append("Each invariant has a stable ID, one sentence, the facts it rests on (../shared/spec/retail-cell-physics-facts.md),\n");
        sb.Append("and one executable check shared by the properties, the fuzzer and the CLI.\n\n");
        sb.Append("## Retail and hardening\n\n");
        sb.Append("Each invariant is labelled `retail` (what retail does; the facts section it rests on) or `hardening` (a rule\n");
        sb.Append("beyond retail that protects a port; the reason). A port that matches retail exactly may fail hardening rules only:\n");
        sb.Append("rejecting NaN is this suite's rule, while retail most likely re-seats a non-finite coordinate in its block's own\n");
        sb.Append("column (facts §6.17), so the retail invariants ask non-finite inputs (an exception is a violation) but leave the\n");
        sb.Append("verdict to the hardening ones. `acphys verify --scope retail|hardening|all` selects; reports count each apart.\n\n");
        sb.Append("| ID | Scope | Statement | Source | Why this scope |\n|---|---|---|---|---|\n");
        foreach (var invariant in InvariantCatalogue.All)
        {
            string scope = invariant.Scope is { } s ? InvariantScope.Name(s) : "-";
            sb.Append("| `").Append(invariant.Id).Append("` | ").Append(scope).Append(" | ").Append(invariant.Statement.Replace("|", "\\|", StringComparison.Ordinal))
              .Append(" | ").Append(invariant.Source).Append(" | ").Append((invariant.ScopeReason ?? "-").Replace("|", "\\|", StringComparison.Ordinal)).Append(" |\n");
        }

        return sb.ToString();
    }
}
