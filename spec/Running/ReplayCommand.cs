using System.Globalization;
using AcPhys.Contract;
using AcPhys.Formats.Corpus;

namespace AcPhys.Spec.Running;

/// <summary>
/// The one command line that replays a failure, ready to copy into a shell, shared by <c>acphys verify</c> and the gate
/// as xunit tests (AcPhys.Xunit), and checked before it is printed: the replay seed the runner reports is tried first,
/// then the invariant's run seed (the whole generated run again, which is deterministic).
/// </summary>
/// <param name="Program">How the tool is invoked (<c>acphys</c>, or the <c>./acphys</c> wrapper's path).</param>
/// <param name="Profile">The run's budget (its cases are the ones a re-run uses).</param>
public sealed record ReplayCommand(string Program, Profile Profile)
{
    /// <summary>Gets the <c>--cases</c> the run was given, if any.</summary>
    public int? Cases { get; init; }

    /// <summary>Gets a value indicating whether the line says <c>--sweeps</c> (a served implementation swept by request).</summary>
    public bool Sweeps { get; init; }

    /// <summary>Gets the mode the bundled reference ran in (<c>--pick</c>, <c>--fidelity</c>, <c>--fault</c>), or null for retail: every option that changes the verdict (issue 41).</summary>
    public CaseMode? Mode { get; init; }

    /// <summary>Gets the words that name the implementation (<c>--impl PATH</c>, <c>--impl-cmd "..."</c>), empty for the reference.</summary>
    public IReadOnlyList<string> Implementation { get; init; } = [];

    /// <summary>Returns the command line that reproduces one failed invariant.</summary>
    /// <param name="result">The failed result.</param>
    /// <param name="impl">The implementation the failure was found on.</param>
    /// <returns>The line, and whether it was seen to reproduce the failure.</returns>
    public (string Line, bool Confirmed) For(InvariantResult result, ICellPhysics impl)
    {
        if (result.Replay is null && result.ExhaustiveCases > 0)
        {
            // Found by an exhaustive sweep: deterministic, and the pr profile sweeps too.
            return (Build(result, seed: null, profile: "pr"), true);
        }

        if (result.Replay is Seed replay && Reproduces(result, impl, replay, 1))
        {
            return (Build(result, replay, Profile.Name), true);
        }

        bool confirmed = Reproduces(result, impl, result.Seed, Profile.CasesPerInvariant);
        return (Build(result, result.Seed, Profile.Name), confirmed);
    }

    /// <summary>Returns the <c>acphys replay</c> line of a written case file (the mode is in the file).</summary>
    /// <param name="caseFile">The case file.</param>
    /// <returns>The line.</returns>
    public string ReplayFile(string caseFile) =>
        string.Join(' ', new[] { Program, "replay", caseFile }.Concat(Implementation).Select(Quote));

    /// <summary>Quotes a word for a POSIX shell when it holds anything beyond the plain characters.</summary>
    /// <param name="word">The word.</param>
    /// <returns>The word, single-quoted when needed.</returns>
    public static string Quote(string word) =>
        word.Length > 0 && word.All(c => char.IsAsciiLetterOrDigit(c) || "_-./,:=+@%".Contains(c))
            ? word
            : "'" + word.Replace("'", "'\\''", StringComparison.Ordinal) + "'";

    private static bool Reproduces(InvariantResult result, ICellPhysics impl, Seed seed, int cases)
    {
        if (result.Violation is null)
        {
            return false;
        }

        var again = result.Invariant.Run(impl, cases, seed, maxClasses: 1);
        return again.Status == ResultStatus.Failed && again.Violation?.CaseText == result.Violation.CaseText;
    }

    private string Build(InvariantResult result, Seed? seed, string profile)
    {
        var words = new List<string> { Program, "verify" };
        if (profile != "pr")
        {
            words.AddRange(["--profile", profile]);
        }

        words.AddRange(["--only", result.Invariant.Id]);
        if (Cases is int n)
        {
            words.AddRange(["--cases", n.ToString(CultureInfo.InvariantCulture)]);
        }

        if (Sweeps)
        {
            words.Add("--sweeps");
        }

        if (seed is Seed s)
        {
            words.AddRange(["--seed", s.ToString()]);
        }

        words.AddRange(Mode?.Words() ?? []);
        words.AddRange(Implementation);
        return string.Join(' ', words.Select(Quote));
    }
}
