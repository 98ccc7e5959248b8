using System.Globalization;
using AcPhys.Spec.Invariants;

namespace AcPhys.Cli.Render;

/// <summary>
/// The second header line of a walk picture: every invariant the walk breaks, each with its first step, and the
/// file's own invariant named apart when the run does not break it (issue 19: the headline named one invariant while
/// the picture showed others).
/// </summary>
internal static class WalkHeadline
{
    /// <summary>Builds the line.</summary>
    /// <param name="steps">The number of steps.</param>
    /// <param name="perStep">The violations of each step (index = step).</param>
    /// <param name="fileInvariant">The invariant the file says found it, or null.</param>
    /// <returns>E.g. <c>1 steps; broken: NEIGHBOUR-SYMMETRY (first at step 0), NO-BOUNDARY-FREEZE (first at step 1)</c>.</returns>
    public static string For(int steps, IReadOnlyList<IReadOnlyList<Violation>> perStep, string? fileInvariant)
    {
        var first = new Dictionary<string, int>(StringComparer.Ordinal);
        for (int i = 0; i < perStep.Count; i++)
        {
            foreach (var v in perStep[i])
            {
                first.TryAdd(v.InvariantId, i);
            }
        }

        string text = string.Create(CultureInfo.InvariantCulture, $"{steps} steps; ")
            + (first.Count == 0
                ? "no violation"
                : $"{first.Count} invariant{(first.Count == 1 ? string.Empty : "s")} broken: "
                    + string.Join(", ", first.OrderBy(p => p.Value).ThenBy(p => p.Key, StringComparer.Ordinal).Select(p => string.Create(CultureInfo.InvariantCulture, $"{p.Key} (first at step {p.Value})"))));
        if (fileInvariant is not null && !first.ContainsKey(fileInvariant))
        {
            text += $"; the file's invariant {fileInvariant} is not broken in this run";
        }

        return text;
    }
}
