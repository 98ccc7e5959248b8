using AcPhys.Spec.Adapters;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>
/// Builds the one command line that replays a failure, ready to copy into a shell, and checks that it does: the
/// replay seed the runner reports is tried first, then the invariant's run seed (the whole generated run again,
/// which is deterministic), so a line is only printed once it has been seen to reproduce the shrunk case.
/// </summary>
internal static class ReplayLine
{
    /// <summary>Gets how to invoke the tool: <c>ACPHYS_COMMAND</c> (the <c>./acphys</c> wrapper sets it to its own path as typed), else <c>acphys</c>.</summary>
    public static string Program => Environment.GetEnvironmentVariable("ACPHYS_COMMAND") is { Length: > 0 } p ? p : "acphys";

    /// <summary>Returns the command line that reproduces one failed invariant.</summary>
    /// <param name="result">The failed result.</param>
    /// <param name="settings">The run's settings (profile, fault).</param>
    /// <param name="impl">The implementation the failure was found on.</param>
    /// <returns>The line, and whether it was seen to reproduce the failure.</returns>
    public static (string Line, bool Confirmed) For(InvariantResult result, VerifySettings settings, ICellPhysics impl)
    {
        if (result.Replay is null && result.ExhaustiveCases > 0)
        {
            // Found by an exhaustive sweep: deterministic, and the pr profile sweeps too.
            return (Build(result, settings, seed: null, profile: "pr"), true);
        }

        if (result.Replay is Seed replay && Reproduces(result, impl, replay, 1))
        {
            return (Build(result, settings, replay, settings.Profile.Name), true);
        }

        bool confirmed = Reproduces(result, impl, result.Seed, settings.Profile.CasesPerInvariant);
        return (Build(result, settings, result.Seed, settings.Profile.Name), confirmed);
    }

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

    private static string Build(InvariantResult result, VerifySettings settings, Seed? seed, string profile)
    {
        var words = new List<string> { Program, "verify" };
        if (profile != "pr")
        {
            words.AddRange(["--profile", profile]);
        }

        words.AddRange(["--only", result.Invariant.Id]);
        if (settings.CasesOverride is int n)
        {
            words.AddRange(["--cases", n.ToString(System.Globalization.CultureInfo.InvariantCulture)]);
        }

        if (settings.Implementation.IsProcess && settings.Profile.Exhaustive)
        {
            words.Add("--sweeps");
        }

        if (seed is Seed s)
        {
            words.AddRange(["--seed", s.ToString()]);
        }

        words.AddRange(settings.Mode.Words()); // --pick, --fidelity, --fault: every option that changes the verdict (issue 41)
        words.AddRange(settings.Implementation.Words());
        return string.Join(' ', words.Select(Quote));
    }
}
