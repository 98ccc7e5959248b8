namespace AcPhys.Formats.Corpus;

/// <summary>
/// The mode the bundled reference ran in when a case was found (issue 41, "replay carries the mode"): the pick, the
/// declared deviations and the planted fault of <c>verify --pick / --fidelity / --fault</c>, so <c>acphys replay FILE</c>
/// judges the case as the run that failed did. Stored as the field <c>mode</c> of a corpus file (docs/corpus-format.md).
/// </summary>
/// <param name="Pick">The pick policy name (<c>current-first</c>), or null for retail.</param>
/// <param name="Fidelity">The declared deviation names (<c>FidelityNames</c>), empty for retail.</param>
/// <param name="Fault">The planted fault id, or null.</param>
public sealed record CaseMode(string? Pick, IReadOnlyList<string> Fidelity, string? Fault)
{
    /// <summary>Gets a value indicating whether the mode is the plain retail reference (nothing to store).</summary>
    public bool IsRetail => Pick is null && Fidelity.Count == 0 && Fault is null;

    /// <summary>Returns the command-line words that choose this mode again (<c>--pick</c>, <c>--fidelity</c>, <c>--fault</c>).</summary>
    /// <returns>The words, unquoted.</returns>
    public IReadOnlyList<string> Words()
    {
        var words = new List<string>();
        if (Pick is not null)
        {
            words.AddRange(["--pick", Pick]);
        }

        if (Fidelity.Count > 0)
        {
            words.AddRange(["--fidelity", string.Join(',', Fidelity)]);
        }

        if (Fault is not null)
        {
            words.AddRange(["--fault", Fault]);
        }

        return words;
    }

    /// <inheritdoc/>
    public bool Equals(CaseMode? other) =>
        other is not null && Pick == other.Pick && Fault == other.Fault && Fidelity.SequenceEqual(other.Fidelity, StringComparer.Ordinal);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(Pick, Fault, string.Join(',', Fidelity));
}
