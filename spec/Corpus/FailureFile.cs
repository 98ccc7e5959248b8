using System.Security.Cryptography;
using System.Text;
using AcPhys.Formats.Corpus;
using AcPhys.Spec.Invariants;

namespace AcPhys.Spec.Corpus;

/// <summary>
/// Writes a violation's (shrunk) case as a corpus file named <c>&lt;INVARIANT-ID&gt;-&lt;content-hash&gt;.json</c>,
/// atomically, so a failure anywhere becomes one file that <c>acphys replay</c> reproduces.
/// </summary>
public static class FailureFile
{
    /// <summary>Renders the entry for a violation, or null when its case type cannot be stored.</summary>
    /// <param name="violation">The violation (its <see cref="Violation.Case"/> must be set).</param>
    /// <param name="foundBy">props, fuzz, …</param>
    /// <param name="seed">The seed that found it.</param>
    /// <param name="mode">The mode the bundled reference ran in (pick, fidelity, fault), stored so a replay judges the same way; null for retail.</param>
    /// <returns>The entry, or null.</returns>
    public static CorpusEntry? EntryFor(Violation violation, string foundBy, string? seed, CaseMode? mode = null) =>
        CorpusEntry.From(violation.Case, $"{violation.InvariantId}: {violation.Message}", violation.InvariantId, foundBy, seed) is { } entry
            ? entry with { Mode = mode is { IsRetail: false } ? mode : null }
            : null;

    /// <summary>Returns the file name for an entry: the invariant ID and the first 8 hex digits of the SHA-256 of its case.</summary>
    /// <param name="entry">The entry.</param>
    /// <returns>The name.</returns>
    public static string NameFor(CorpusEntry entry)
    {
        string body = CorpusJson.Write(entry with { Title = string.Empty, Seed = null, FoundBy = "spec" });
        string hash = Convert.ToHexStringLower(SHA256.HashData(Encoding.UTF8.GetBytes(body)))[..8];
        return $"{entry.Invariant ?? "CASE"}-{hash}.json";
    }

    /// <summary>Writes the violation's case into a folder; returns the path, or null when the case cannot be stored.</summary>
    /// <param name="violation">The violation.</param>
    /// <param name="folder">The folder (created if missing).</param>
    /// <param name="foundBy">props, fuzz, …</param>
    /// <param name="seed">The seed that found it.</param>
    /// <param name="mode">The mode the bundled reference ran in, or null for retail.</param>
    /// <returns>The path written.</returns>
    public static string? Write(Violation violation, string folder, string foundBy, string? seed, CaseMode? mode = null)
    {
        var entry = EntryFor(violation, foundBy, seed, mode);
        if (entry is null)
        {
            return null;
        }

        string path = Path.Combine(folder, NameFor(entry));
        AtomicFile.WriteAllText(path, CorpusJson.Write(entry));
        return path;
    }
}
