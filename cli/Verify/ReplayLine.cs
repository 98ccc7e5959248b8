using AcPhys.Contract;
using AcPhys.Spec.Running;

namespace AcPhys.Cli.Verify;

/// <summary>
/// The replay line of a <c>verify</c> run: spec's <see cref="ReplayCommand"/> (shared with the gate as xunit tests)
/// built from the run's settings.
/// </summary>
internal static class ReplayLine
{
    /// <summary>Gets how to invoke the tool: <c>ACPHYS_COMMAND</c> (the <c>./acphys</c> wrapper sets it to its own path as typed), else <c>acphys</c>.</summary>
    public static string Program => ToolEnvironment.Process.Command;

    /// <summary>Returns the replay command of a run: its profile, cases, fault and implementation words.</summary>
    /// <param name="settings">The run's settings.</param>
    /// <returns>The command.</returns>
    public static ReplayCommand Command(VerifySettings settings) => new(Program, settings.Profile)
    {
        Cases = settings.CasesOverride,
        Sweeps = settings.Implementation.IsProcess && settings.Profile.Exhaustive,
        Mode = settings.Mode,
        Implementation = [.. settings.Implementation.Words()],
    };

    /// <summary>Returns the command line that reproduces one failed invariant.</summary>
    /// <param name="result">The failed result.</param>
    /// <param name="settings">The run's settings (profile, fault).</param>
    /// <param name="impl">The implementation the failure was found on.</param>
    /// <returns>The line, and whether it was seen to reproduce the failure.</returns>
    public static (string Line, bool Confirmed) For(InvariantResult result, VerifySettings settings, ICellPhysics impl) => Command(settings).For(result, impl);

    /// <summary>Quotes a word for a POSIX shell when it holds anything beyond the plain characters.</summary>
    /// <param name="word">The word.</param>
    /// <returns>The word, single-quoted when needed.</returns>
    public static string Quote(string word) => ReplayCommand.Quote(word);
}
