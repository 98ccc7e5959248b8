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
        sb.Append("| ID | Statement | Source |\n|---|---|---|\n");
        foreach (var invariant in InvariantCatalogue.All)
        {
            sb.Append("| `").Append(invariant.Id).Append("` | ").Append(invariant.Statement.Replace("|", "\\|", StringComparison.Ordinal))
              .Append(" | ").Append(invariant.Source).Append(" |\n");
        }

        return sb.ToString();
    }
}
