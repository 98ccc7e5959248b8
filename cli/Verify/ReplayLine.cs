using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>Builds the one command line that replays a failure, ready to copy into a shell.</summary>
internal static class ReplayLine
{
    /// <summary>Gets how to invoke the tool: <c>ACPHYS_COMMAND</c> (the <c>./acphys</c> wrapper sets it to its own path as typed), else <c>acphys</c>.</summary>
    public static string Program => Environment.GetEnvironmentVariable("ACPHYS_COMMAND") is { Length: > 0 } p ? p : "acphys";

    /// <summary>Returns the command line that reproduces one failed invariant.</summary>
    /// <param name="result">The failed result.</param>
    /// <param name="settings">The run's settings (for the fault).</param>
    /// <returns>The command line. A generated failure is replayed by its replay seed; an exhaustive-sweep failure by
    /// re-running the invariant under the deterministic pr profile.</returns>
    public static string For(InvariantResult result, VerifySettings settings)
    {
        var words = new List<string> { Program, "verify", "--only", result.Invariant.Id };
        if (result.Replay is Seed replay)
        {
            words.AddRange(["--seed", replay.ToString()]);
        }
        else if (settings.FixedSeed is Seed fixedSeed)
        {
            words.AddRange(["--seed", fixedSeed.ToString()]);
        }

        if (settings.Fault is not null)
        {
            words.AddRange(["--fault", settings.Fault.Id]);
        }

        return string.Join(' ', words.Select(Quote));
    }

    /// <summary>Quotes a word for a POSIX shell when it holds anything beyond the plain characters.</summary>
    /// <param name="word">The word.</param>
    /// <returns>The word, single-quoted when needed.</returns>
    public static string Quote(string word) =>
        word.Length > 0 && word.All(c => char.IsAsciiLetterOrDigit(c) || "_-./,:=+@%".Contains(c))
            ? word
            : "'" + word.Replace("'", "'\\''", StringComparison.Ordinal) + "'";
}
