namespace AcPhys.Formats.Corpus;

/// <summary>What found a stored case (a corpus entry's <c>foundBy</c>): the one list every reader checks against.</summary>
public static class FinderNames
{
    /// <summary>Written by hand.</summary>
    public const string Hand = "hand";

    /// <summary>Found by <c>acphys verify</c> (the pr gate or any profile).</summary>
    public const string Verify = "verify";

    /// <summary>Found by a property test (<c>dotnet test props</c>).</summary>
    public const string Props = "props";

    /// <summary>Found by a fuzz campaign (<c>acphys fuzz</c>).</summary>
    public const string Fuzz = "fuzz";

    /// <summary>Found by <c>acphys diff</c> (a divergence from the reference).</summary>
    public const string Diff = "diff";

    /// <summary>Minimised from a port's own capture (<c>acphys capture check --minimise</c>).</summary>
    public const string Capture = "capture";

    /// <summary>Made by the suite itself (examples, normal forms).</summary>
    public const string Spec = "spec";

    /// <summary>Gets every known finder.</summary>
    public static IReadOnlyList<string> All { get; } = [Hand, Props, Fuzz, Spec, Diff, Verify, Capture];

    /// <summary>Gets the message for an unknown finder.</summary>
    public static string Expected => "expected hand, props, fuzz, spec, diff, verify or capture";

    /// <summary>Tests whether a finder name is known.</summary>
    /// <param name="name">The name.</param>
    /// <returns>True when known.</returns>
    public static bool IsKnown(string name) => All.Contains(name, StringComparer.Ordinal);
}
